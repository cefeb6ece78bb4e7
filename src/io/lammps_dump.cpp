#include "io/lammps_dump.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <type_traits>
#include <fstream>
#include <sstream>
#include <unordered_set>
#include <vector>

#include "core/errors.hpp"
#include "io/text.hpp"

namespace trapdem {

namespace {


class Reader {
 public:
  Reader(const std::string& text, const std::string& source) : source_(source) {
    std::size_t start = 0;
    while (start <= text.size()) {
      std::size_t end = text.find('\n', start);
      if (end == std::string::npos) end = text.size();
      lines_.push_back(std::string_view(text).substr(start, end - start));
      start = end + 1;
    }
    if (!lines_.empty() && lines_.back().empty()) lines_.pop_back();
  }

  [[noreturn]] void fail(std::size_t line, const std::string& what) const {
    throw InputError(source_ + ":" + std::to_string(line + 1) + ": " + what);
  }
  bool done() const { return next_ >= lines_.size(); }
  std::size_t line_number() const { return next_; }
  std::string_view take() {
    if (done()) fail(lines_.size() == 0 ? 0 : lines_.size() - 1, "the file ends early (a dump section is incomplete)");
    return lines_[next_++];
  }
  template <class T>
  T number(std::string_view word, std::size_t line, const char* what) const {
    T value{};
    const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (ec != std::errc() || ptr != word.data() + word.size()) {
      fail(line, std::string(what) + ": '" + std::string(word) + "' is not a number");
    }
    if constexpr (std::is_floating_point_v<T>) {
      // from_chars reads "nan" and "inf": no coordinate, radius or bound of a dump means either.
      if (!std::isfinite(value)) fail(line, std::string(what) + ": '" + std::string(word) + "' is not a finite number");
    }
    return value;
  }

 private:
  std::string source_;
  std::vector<std::string_view> lines_;
  std::size_t next_ = 0;
};

}  // namespace

DumpAtoms parse_dump_atoms(const std::string& text, const std::string& source) {
  Reader in(text, source);
  DumpAtoms out;
  Snapshot& s = out.snapshot;
  bool have_step = false, have_count = false, have_box = false, have_atoms = false;
  std::size_t count = 0;
  double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  while (!in.done()) {
    const std::size_t line = in.line_number();
    const std::string_view header = in.take();
    const auto words = split_words(header);
    if (words.empty()) continue;
    if (words[0] != "ITEM:") in.fail(line, "expected an 'ITEM:' line, found '" + std::string(header) + "'");
    const std::string item(header.substr(header.find("ITEM:") + 5));
    if (item.find("TIMESTEP") != std::string::npos) {
      if (have_step) in.fail(line, "a second TIMESTEP: give one dump file per snapshot");
      const std::size_t l = in.line_number();
      const auto w = split_words(in.take());
      if (w.size() != 1) in.fail(l, "expected the timestep (one integer)");
      s.step = in.number<std::int64_t>(w[0], l, "timestep");
      have_step = true;
    } else if (item.find("NUMBER OF ATOMS") != std::string::npos) {
      const std::size_t l = in.line_number();
      const auto w = split_words(in.take());
      if (w.size() != 1) in.fail(l, "expected the number of atoms (one integer)");
      const auto n = in.number<std::int64_t>(w[0], l, "number of atoms");
      if (n < 0) in.fail(l, "negative number of atoms");
      count = static_cast<std::size_t>(n);
      have_count = true;
    } else if (item.find("BOX BOUNDS") != std::string::npos) {
      for (int k = 0; k < 3; ++k) {
        const std::size_t l = in.line_number();
        const auto w = split_words(in.take());
        if (w.size() < 2) in.fail(l, "expected the box bounds 'lo hi'");
        lo[k] = in.number<double>(w[0], l, "box bound");
        hi[k] = in.number<double>(w[1], l, "box bound");
      }
      have_box = true;
    } else if (item.find("ATOMS") != std::string::npos) {
      if (!have_count) in.fail(line, "ITEM: ATOMS before ITEM: NUMBER OF ATOMS");
      if (have_atoms) in.fail(line, "a second ITEM: ATOMS section: give one dump file per snapshot");
      const auto columns = split_words(std::string_view(header).substr(header.find("ATOMS") + 5));
      auto find = [&](std::initializer_list<const char*> names, bool& scaled) -> std::ptrdiff_t {
        for (const char* name : names) {
          for (std::size_t c = 0; c < columns.size(); ++c) {
            if (columns[c] == name) {
              scaled = std::string_view(name).size() == 2 && name[1] == 's';
              return static_cast<std::ptrdiff_t>(c);
            }
          }
        }
        return -1;
      };
      bool scaled[3] = {false, false, false}, unused = false, is_radius = true;
      const std::ptrdiff_t cid = find({"id"}, unused);
      const std::ptrdiff_t cx[3] = {find({"x", "xu", "xs"}, scaled[0]), find({"y", "yu", "ys"}, scaled[1]),
                                    find({"z", "zu", "zs"}, scaled[2])};
      std::ptrdiff_t cr = find({"radius"}, unused);
      if (cr < 0) {
        cr = find({"diameter"}, unused);
        is_radius = false;
      }
      std::string missing;
      if (cid < 0) missing += " id";
      if (cx[0] < 0) missing += " x";
      if (cx[1] < 0) missing += " y";
      if (cx[2] < 0) missing += " z";
      if (cr < 0) missing += " radius";
      if (!missing.empty()) {
        in.fail(line, "the ATOMS columns lack" + missing + " (dump with: id x y z radius)");
      }
      // Optional vectors, read when all three components are there (a lone vx is ignored, as
      // other columns are).
      auto optional_vector = [&](const char* const (&names)[3]) -> std::array<std::ptrdiff_t, 3> {
        std::array<std::ptrdiff_t, 3> c{};
        int found = 0;
        for (int k = 0; k < 3; ++k) found += (c[k] = find({names[k]}, unused)) >= 0;
        if (found != 3) c = {-1, -1, -1};
        return c;
      };
      const auto cv = optional_vector({"vx", "vy", "vz"});
      const auto cw = optional_vector({"omegax", "omegay", "omegaz"});
      const std::ptrdiff_t cdensity = find({"density"}, unused);
      if ((scaled[0] || scaled[1] || scaled[2]) && !have_box) in.fail(line, "scaled coordinates need ITEM: BOX BOUNDS first");
      std::unordered_set<std::int64_t> seen;
      s.id.reserve(count);
      for (std::size_t a = 0; a < count; ++a) {
        const std::size_t l = in.line_number();
        if (in.done()) in.fail(l - 1, "expected " + std::to_string(count) + " atom lines, found " + std::to_string(a));
        const auto w = split_words(in.take());
        if (!w.empty() && w[0] == "ITEM:") {
          in.fail(l, "expected " + std::to_string(count) + " atom lines, found " + std::to_string(a));
        }
        if (w.size() < columns.size()) {
          in.fail(l, "expected " + std::to_string(columns.size()) + " columns, found " + std::to_string(w.size()));
        }
        const auto id = in.number<std::int64_t>(w[static_cast<std::size_t>(cid)], l, "id");
        if (!seen.insert(id).second) in.fail(l, "id " + std::to_string(id) + " appears twice");
        Vec3 p;
        double* comp[3] = {&p.x, &p.y, &p.z};
        for (int k = 0; k < 3; ++k) {
          double v = in.number<double>(w[static_cast<std::size_t>(cx[k])], l, "coordinate");
          if (scaled[k]) v = lo[k] + v * (hi[k] - lo[k]);
          if (!std::isfinite(v)) in.fail(l, "the scaled coordinate maps to a non-finite position (check the box bounds)");
          *comp[k] = v;
        }
        const double r = in.number<double>(w[static_cast<std::size_t>(cr)], l, is_radius ? "radius" : "diameter");
        if (!(r > 0.0)) in.fail(l, "the radius of atom " + std::to_string(id) + " must be positive");
        s.id.push_back(id);
        s.position.push_back(p);
        s.radius.push_back(is_radius ? r : 0.5 * r);
        out.line.push_back(l + 1);
        auto vector_at = [&](const std::array<std::ptrdiff_t, 3>& c, const char* what) {
          if (c[0] < 0) return Vec3{};
          return Vec3{in.number<double>(w[static_cast<std::size_t>(c[0])], l, what),
                      in.number<double>(w[static_cast<std::size_t>(c[1])], l, what),
                      in.number<double>(w[static_cast<std::size_t>(c[2])], l, what)};
        };
        s.velocity.push_back(vector_at(cv, "velocity"));
        s.angular_velocity.push_back(vector_at(cw, "angular velocity"));
        if (cdensity >= 0) {
          const double rho = in.number<double>(w[static_cast<std::size_t>(cdensity)], l, "density");
          if (!(rho > 0.0)) in.fail(l, "the density of atom " + std::to_string(id) + " must be positive");
          out.density.push_back(rho);
        }
      }
      have_atoms = true;
    } else {
      in.fail(line, "unknown section '" + std::string(header) + "'");
    }
  }
  if (!have_atoms) throw InputError(source + ": no ITEM: ATOMS section (not a LAMMPS/LIGGGHTS text dump?)");
  s.image.assign(s.id.size(), Int3{});
  return out;
}

Snapshot parse_dump(const std::string& text, const std::string& source) {
  return std::move(parse_dump_atoms(text, source).snapshot);
}

DumpAtoms read_dump_atoms(const std::filesystem::path& path) {
  // A dump that is not there is a wrong name given (an input error, exit 2); one that is there
  // and cannot be read, a file error (4): the exit-code contract (README.md).
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path.string() + ": no such dump file");
  if (std::filesystem::is_directory(path, ec)) throw InputError(path.string() + ": a folder, not a dump file");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw FileError(path.string() + ": cannot open the dump file");
  std::ostringstream text;
  text << file.rdbuf();
  if (file.bad()) throw FileError(path.string() + ": cannot read the dump file");
  return parse_dump_atoms(text.str(), path.string());
}

Snapshot read_dump_file(const std::filesystem::path& path) { return std::move(read_dump_atoms(path).snapshot); }

}  // namespace trapdem
