#include "io/lammps_data.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <istream>
#include <memory>
#include <ostream>
#include <string_view>
#include <unordered_map>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "core/errors.hpp"
#include "io/text.hpp"

namespace trapdem {

namespace {

constexpr const char* kAtomsColumns = "id type diameter density x y z [ix iy iz]";
constexpr const char* kVelocityColumns = "id vx vy vz wx wy wz";

struct Line {
  std::size_t number = 0;              // 1-based line number in the file
  std::vector<std::string_view> tokens;
  std::string comment;                 // text after '#', trimmed
};


std::string join(const std::vector<std::string_view>& tokens, std::size_t from) {
  std::string out;
  for (std::size_t q = from; q < tokens.size(); ++q) {
    if (q > from) out.push_back(' ');
    out.append(tokens[q]);
  }
  return out;
}

std::string trim(std::string_view s) {
  std::size_t a = 0, b = s.size();
  while (a < b && (s[a] == ' ' || s[a] == '\t' || s[a] == '\r')) ++a;
  while (b > a && (s[b - 1] == ' ' || s[b - 1] == '\t' || s[b - 1] == '\r')) --b;
  return std::string(s.substr(a, b - a));
}

bool parse_double(std::string_view t, double& value) {
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  const char* end = t.data() + t.size();
  auto [ptr, ec] = std::from_chars(t.data(), end, value);
  return ec == std::errc() && ptr == end;
}

bool parse_int(std::string_view t, std::int64_t& value) {
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  const char* end = t.data() + t.size();
  auto [ptr, ec] = std::from_chars(t.data(), end, value);
  return ec == std::errc() && ptr == end;
}

bool looks_numeric(std::string_view t) {
  double d;
  return parse_double(t, d);
}

class Parser {
 public:
  Parser(std::string name) : name_(std::move(name)) {}

  [[noreturn]] void fail(std::size_t line, const std::string& what) const {
    throw InputError(fmt::format("{}:{}: {}", name_, line, what));
  }

  double number(const Line& l, std::size_t col, const char* column_name, const char* layout) const {
    double v;
    if (!parse_double(l.tokens[col], v) || !std::isfinite(v))
      fail(l.number, fmt::format("column {} ({}) is '{}', expected a number; the line should read: {}", col + 1,
                                 column_name, l.tokens[col], layout));
    return v;
  }

  std::int64_t integer(const Line& l, std::size_t col, const char* column_name, const char* layout) const {
    std::int64_t v;
    if (!parse_int(l.tokens[col], v))
      fail(l.number, fmt::format("column {} ({}) is '{}', expected an integer; the line should read: {}", col + 1,
                                 column_name, l.tokens[col], layout));
    return v;
  }

  LammpsData parse(std::istream& in) {
    // Read every line once; keep the text alive for the string_views.
    std::string text;
    std::size_t number = 0;
    while (std::getline(in, text)) {
      ++number;
      if (number == 1) {
        data_.title = trim(text);
        continue;
      }
      store_.push_back(std::move(text));
      const std::string& s = store_.back();
      Line l;
      l.number = number;
      const std::size_t hash = s.find('#');
      const std::string_view body = std::string_view(s).substr(0, hash);
      if (hash != std::string::npos) l.comment = trim(std::string_view(s).substr(hash + 1));
      l.tokens = split_words(body);
      if (!l.tokens.empty()) lines_.push_back(std::move(l));
    }
    end_line_ = number;
    if (number == 0) fail(1, "empty file; expected a LAMMPS data file (title line, header, Atoms section)");
    header();
    sections();
    finish();
    return std::move(data_);
  }

 private:
  void header() {
    for (; pos_ < lines_.size(); ++pos_) {
      const Line& l = lines_[pos_];
      if (!looks_numeric(l.tokens[0])) return;  // the first section
      std::size_t k = 0;
      while (k < l.tokens.size() && looks_numeric(l.tokens[k])) ++k;
      const std::string keyword = join(l.tokens, k);
      if (keyword == "atoms") {
        if (k != 1) fail(l.number, "expected 'N atoms'");
        std::int64_t n;
        if (!parse_int(l.tokens[0], n) || n < 0)
          fail(l.number, fmt::format("'{}' atoms: expected a non-negative integer count", l.tokens[0]));
        atoms_ = n;
        atoms_line_ = l.number;
      } else if (keyword == "xlo xhi" || keyword == "ylo yhi" || keyword == "zlo zhi") {
        const int axis = keyword[0] - 'x';
        if (k != 2) fail(l.number, fmt::format("expected '{0}lo {0}hi' after two numbers", "xyz"[axis]));
        const double lo = number(l, 0, "lo", "lo hi");
        const double hi = number(l, 1, "hi", "lo hi");
        if (!(hi > lo)) fail(l.number, fmt::format("box bounds {} {}: expected {}hi > {}lo", lo, hi, "xyz"[axis], "xyz"[axis]));
        data_.box_lower[axis] = lo;
        data_.box_upper[axis] = hi;
        have_bounds_[axis] = true;
      } else if (keyword.empty()) {
        fail(l.number, "header line holds only numbers; expected a keyword such as 'atoms' or 'xlo xhi'");
      }
      // Other header keywords (atom types, bonds, xy xz yz, ...) are accepted and ignored.
    }
  }

  void sections() {
    while (pos_ < lines_.size()) {
      const Line& head = lines_[pos_];
      const std::string name = join(head.tokens, 0);
      ++pos_;
      const std::size_t begin = pos_;
      while (pos_ < lines_.size() && looks_numeric(lines_[pos_].tokens[0])) ++pos_;
      if (name == "Atoms") {
        if (have_atoms_) fail(head.number, "a second Atoms section; expected one");
        if (!head.comment.empty() && head.comment != "sphere")
          fail(head.number, fmt::format("Atoms section of atom_style '{}'; expected atom_style sphere ({})",
                                        head.comment, kAtomsColumns));
        atoms(head, begin, pos_);
      } else if (name == "Velocities") {
        if (have_velocities_) fail(head.number, "a second Velocities section; expected one");
        velocities_index_ = begin - 1;
        velocity_begin_ = begin;
        velocity_end_ = pos_;
        have_velocities_ = true;
      }
      // Other sections (Masses, Bonds, ...) are skipped.
    }
  }

  void check_count(const Line& head, std::size_t found, const char* what) const {
    if (atoms_ < 0) return;
    if (found != std::size_t(atoms_)) {
      const std::size_t at = found > std::size_t(atoms_) ? lines_[head_index(head) + 1 + atoms_].number : head.number;
      fail(at, fmt::format("{} section has {} lines; expected {} (the header's '{} atoms', line {})", what, found,
                           atoms_, atoms_, atoms_line_));
    }
  }

  std::size_t head_index(const Line& head) const {
    for (std::size_t k = 0; k < lines_.size(); ++k)
      if (lines_[k].number == head.number) return k;
    return 0;
  }

  void atoms(const Line& head, std::size_t begin, std::size_t end) {
    have_atoms_ = true;
    if (atoms_ < 0) fail(head.number, "Atoms section before an 'N atoms' header line; expected the header first");
    check_count(head, end - begin, "Atoms");
    Particles& p = data_.particles;
    p.reserve(end - begin);
    data_.type.reserve(end - begin);
    data_.line.reserve(end - begin);
    for (std::size_t k = begin; k < end; ++k) {
      const Line& l = lines_[k];
      if (l.tokens.size() != 7 && l.tokens.size() != 10)
        fail(l.number, fmt::format("Atoms line has {} columns; expected 7 or 10 for atom_style sphere: {}",
                                   l.tokens.size(), kAtomsColumns));
      const std::int64_t id = integer(l, 0, "id", kAtomsColumns);
      const std::int64_t type = integer(l, 1, "type", kAtomsColumns);
      const double diameter = number(l, 2, "diameter", kAtomsColumns);
      const double density = number(l, 3, "density", kAtomsColumns);
      const Vec3 x{number(l, 4, "x", kAtomsColumns), number(l, 5, "y", kAtomsColumns), number(l, 6, "z", kAtomsColumns)};
      if (!(diameter > 0.0))
        fail(l.number, fmt::format("diameter {} of atom {}; expected a positive diameter (point particles are not supported)",
                                   diameter, id));
      if (!(density > 0.0)) fail(l.number, fmt::format("density {} of atom {}; expected a positive density", density, id));
      if (!index_of_.emplace(id, p.size()).second)
        fail(l.number, fmt::format("atom id {} appears twice; expected unique ids", id));
      p.add(id, x, 0.5 * diameter, density);
      data_.type.push_back(static_cast<int>(type));
      data_.line.push_back(l.number);
      if (l.tokens.size() == 10) {
        Int3& im = p.image.back();
        im.x = static_cast<std::int32_t>(integer(l, 7, "ix", kAtomsColumns));
        im.y = static_cast<std::int32_t>(integer(l, 8, "iy", kAtomsColumns));
        im.z = static_cast<std::int32_t>(integer(l, 9, "iz", kAtomsColumns));
      }
    }
  }

  void velocities() {
    const Line& head = lines_[velocities_index_];
    check_count(head, velocity_end_ - velocity_begin_, "Velocities");
    Particles& p = data_.particles;
    for (std::size_t k = velocity_begin_; k < velocity_end_; ++k) {
      const Line& l = lines_[k];
      if (l.tokens.size() != 7)
        fail(l.number, fmt::format("Velocities line has {} columns; expected 7 for atom_style sphere: {}",
                                   l.tokens.size(), kVelocityColumns));
      const std::int64_t id = integer(l, 0, "id", kVelocityColumns);
      const auto it = index_of_.find(id);
      if (it == index_of_.end()) fail(l.number, fmt::format("velocity of atom id {}; expected an id of the Atoms section", id));
      p.velocity[it->second] = {number(l, 1, "vx", kVelocityColumns), number(l, 2, "vy", kVelocityColumns),
                                number(l, 3, "vz", kVelocityColumns)};
      p.angular_velocity[it->second] = {number(l, 4, "wx", kVelocityColumns), number(l, 5, "wy", kVelocityColumns),
                                        number(l, 6, "wz", kVelocityColumns)};
    }
    data_.has_velocities = true;
  }

  void finish() {
    if (atoms_ < 0) fail(end_line_, "no 'N atoms' header line; expected one before the Atoms section");
    for (int a = 0; a < 3; ++a)
      if (!have_bounds_[a]) fail(end_line_, fmt::format("no '{0}lo {0}hi' header line; expected the box bounds", "xyz"[a]));
    if (!have_atoms_) fail(end_line_, fmt::format("no Atoms section; expected 'Atoms # sphere' followed by {} lines of {}",
                                                  atoms_, kAtomsColumns));
    if (have_velocities_) velocities();
  }

  std::string name_;
  // A list whose elements never move, so that tokens (string_views) stay valid while reading.
  struct Store {
    std::vector<std::unique_ptr<std::string>> items;
    void push_back(std::string s) { items.push_back(std::make_unique<std::string>(std::move(s))); }
    const std::string& back() const { return *items.back(); }
  } store_;
  std::vector<Line> lines_;
  std::size_t pos_ = 0;
  std::size_t end_line_ = 0;
  LammpsData data_;
  std::int64_t atoms_ = -1;
  std::size_t atoms_line_ = 0;
  bool have_bounds_[3] = {false, false, false};
  bool have_atoms_ = false;
  bool have_velocities_ = false;
  std::size_t velocities_index_ = 0, velocity_begin_ = 0, velocity_end_ = 0;
  std::unordered_map<std::int64_t, std::size_t> index_of_;
};

}  // namespace

LammpsData parse_lammps_data(std::istream& in, const std::string& name) { return Parser(name).parse(in); }

LammpsData read_lammps_data(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot open the LAMMPS data file; expected a readable file", path));
  return parse_lammps_data(in, path);
}

void write_lammps_data(std::ostream& out, const Particles& p, const Vec3& lo, const Vec3& hi,
                       const LammpsWriteOptions& options) {
  if (!options.type.empty() && options.type.size() != p.size())
    throw InputError(fmt::format("write_lammps_data: {} types given for {} particles; expected one per particle",
                                 options.type.size(), p.size()));
  int types = 1;
  for (int t : options.type) types = std::max(types, t);
  fmt::print(out, "{}\n\n{} atoms\n{} atom types\n\n", options.title, p.size(), types);
  fmt::print(out, "{:.17g} {:.17g} xlo xhi\n{:.17g} {:.17g} ylo yhi\n{:.17g} {:.17g} zlo zhi\n\n", lo.x, hi.x, lo.y,
             hi.y, lo.z, hi.z);
  fmt::print(out, "Atoms # sphere\n\n");
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3& x = p.position[i];
    const Int3& im = p.image[i];
    fmt::print(out, "{} {} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {} {} {}\n", p.id[i],
               options.type.empty() ? 1 : options.type[i], 2.0 * p.radius[i], p.density(i), x.x, x.y, x.z, im.x, im.y,
               im.z);
  }
  if (options.velocities) {
    fmt::print(out, "\nVelocities\n\n");
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec3& v = p.velocity[i];
      const Vec3& w = p.angular_velocity[i];
      fmt::print(out, "{} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g}\n", p.id[i], v.x, v.y, v.z, w.x, w.y, w.z);
    }
  }
}

void write_lammps_data(const std::string& path, const Particles& p, const Vec3& lo, const Vec3& hi,
                       const LammpsWriteOptions& options) {
  std::ofstream out(path);
  if (!out) throw InputError(fmt::format("{}: cannot open for writing; expected a writable path", path));
  write_lammps_data(out, p, lo, hi, options);
  out.flush();
  if (!out) throw InputError(fmt::format("{}: write failed (disk full?)", path));
}

}  // namespace trapdem
