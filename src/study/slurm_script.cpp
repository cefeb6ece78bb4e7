#include "study/slurm_script.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace trapdem {

namespace {

// Seconds before the time limit at which Slurm sends the batch process SIGTERM (--signal): time for
// the run to finish its step and write its checkpoint before the kill (Slurm's own SIGTERM at the
// limit leaves KillWait, 30 s by default, which a paper-scale checkpoint on a busy file system may
// exceed). Five minutes, or a tenth of a shorter limit; five minutes without --time.
int signal_lead_seconds(const SlurmOptions& o) {
  if (o.time.empty()) return 300;
  return int(std::clamp<std::int64_t>(slurm_time_seconds(o.time) / 10, 1, 300));
}

std::string sbatch_lines(const std::string& job_name, const SlurmOptions& o, const std::string& output) {
  std::string s = fmt::format("#SBATCH --job-name={}\n", shell_quoted(job_name));
  s += fmt::format("#SBATCH --cpus-per-task={}\n", o.cpus_per_task);
  if (!o.partition.empty()) s += fmt::format("#SBATCH --partition={}\n", o.partition);
  if (!o.time.empty()) s += fmt::format("#SBATCH --time={}\n", o.time);
  s += fmt::format("#SBATCH --output={}\n", shell_quoted(output));
  s += "#SBATCH --open-mode=append\n";  // a requeued or resubmitted task adds to its output
  for (const std::string& arg : o.sbatch_args) s += fmt::format("#SBATCH {}\n", arg);
  return s;
}

std::string comment_lines(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& line : lines) s += line.empty() ? "#\n" : "# " + line + "\n";
  return s;
}

}  // namespace

std::string shell_quoted(const std::string& text) {
  const bool plain = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || std::string_view("-_./=:,+%@").find(c) != std::string_view::npos;
  });
  if (plain) return text;
  std::string s = "'";
  for (char c : text) s += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return s + "'";
}

std::string shell_command(const std::vector<std::string>& words) {
  std::string s;
  for (const std::string& w : words) {
    if (!s.empty()) s += ' ';
    s += shell_quoted(w);
  }
  return s;
}

std::string array_ranges(std::vector<int> indices) {
  std::sort(indices.begin(), indices.end());
  indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
  std::string s;
  for (std::size_t k = 0; k < indices.size();) {
    std::size_t end = k;
    while (end + 1 < indices.size() && indices[end + 1] == indices[end] + 1) ++end;
    if (!s.empty()) s += ',';
    s += end == k ? std::to_string(indices[k]) : fmt::format("{}-{}", indices[k], indices[end]);
    k = end + 1;
  }
  return s;
}

std::string array_script_text(const SlurmArrayScript& a) {
  std::string s = "#!/bin/bash\n";
  s += comment_lines(a.comment);
  s += sbatch_lines(a.job_name, a.options, (a.log_folder / "%x-%A_%a.out").string());
  s += fmt::format("#SBATCH --array={}\n", array_ranges(a.array));
  // B: the batch process itself (the run, after exec) gets SIGTERM ahead of the time limit.
  s += fmt::format("#SBATCH --signal=B:TERM@{}\n", signal_lead_seconds(a.options));
  s += R"(
set -euo pipefail
trapdem=)" + shell_quoted(a.trapdem.string()) + R"(
threads=${SLURM_CPUS_PER_TASK:-1}

# run_case DIR CONFIG [--set KEY=VALUE ...]: the run in DIR, started, resumed or skipped by what the
# folder holds, so that a requeued task, or one killed at its time limit and submitted again, carries
# on from its checkpoint. `exec`: the run is the job's process and gets Slurm's SIGTERM itself
# (it then writes a checkpoint and stops).
run_case() {
  local dir=$1 config=$2
  shift 2
  if [ -f "$dir/run.json" ] && grep -Eq '"complete": *true' "$dir/run.json"; then
    echo "$dir: finished before, nothing to do"
    exit 0
  fi
  if [ -f "$dir/checkpoint.h5" ] || [ -f "$dir/resolved.toml" ]; then
    exec "$trapdem" run --resume "$dir" --threads "$threads" --quiet
  fi
  exec "$trapdem" run "$config" --out "$dir" --threads "$threads" --quiet "$@"
}

case "${SLURM_ARRAY_TASK_ID:-}" in
)";
  int first = 0, last = 0;
  for (const SlurmScriptTask& t : a.tasks) {
    first = first ? std::min(first, t.index) : t.index;
    last = std::max(last, t.index);
    s += fmt::format("  {})  # {}\n    run_case {} \\\n      {}", t.index, t.title, shell_quoted(t.dir.string()),
                     shell_quoted(t.config.string()));
    for (const std::string& o : t.overrides) s += fmt::format(" \\\n      --set {}", shell_quoted(o));
    s += " ;;\n";
  }
  s += fmt::format("  *)\n    echo \"array task '${{SLURM_ARRAY_TASK_ID:-}}': not a task of this script ({}-{})\" >&2\n"
                   "    exit 2 ;;\nesac\n", first, last);
  return s;
}

std::string report_script_text(const SlurmReportScript& r) {
  std::string s = "#!/bin/bash\n";
  s += comment_lines(r.comment);
  s += sbatch_lines(r.job_name, r.options, (r.log_folder / "%x-%j.out").string());
  s += "\nset -euo pipefail\n";
  s += fmt::format("exec {}", shell_quoted(r.trapdem.string()));
  // One line per option with its value ("--out DIR"), the rest one a line.
  for (std::size_t k = 0; k < r.arguments.size(); ++k) {
    s += fmt::format(" \\\n  {}", shell_quoted(r.arguments[k]));
    const bool takes_value = r.arguments[k].rfind("--", 0) == 0 && k + 1 < r.arguments.size() &&
                             r.arguments[k + 1].rfind("--", 0) != 0;
    if (takes_value) {
      s += ' ';
      s += shell_quoted(r.arguments[++k]);
    }
  }
  s += " \\\n  --threads \"${SLURM_CPUS_PER_TASK:-1}\"\n";
  return s;
}

}  // namespace trapdem
