// The study report's CSV files (metrics.csv, case_summary.csv) read back by a CSV reader (RFC 4180):
// every row has the header's columns, and a label with a comma or quotes comes back as written.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "study/study_report.hpp"

using namespace trapdem;

namespace {

// A CSV reader as a script's (Python's csv module, a spreadsheet) reads RFC 4180: rows of fields,
// a quoted field may hold commas, doubled quotes and line breaks.
std::vector<std::vector<std::string>> read_csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows(1);
  std::string field;
  bool quoted = false, in_quotes = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_quotes) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        in_quotes = false;
      } else {
        field += c;
      }
    } else if (c == '"' && field.empty() && !quoted) {
      in_quotes = quoted = true;
    } else if (c == ',') {
      rows.back().push_back(field);
      field.clear();
      quoted = false;
    } else if (c == '\n') {
      rows.back().push_back(field);
      field.clear();
      quoted = false;
      rows.emplace_back();
    } else {
      field += c;
    }
  }
  if (rows.back().empty()) rows.pop_back();
  return rows;
}

StudyReportInput one_case_labelled(const std::string& label) {
  CaseSummary run;
  run.name = "all-step04";
  run.label = label;
  run.replicate = true;
  run.seed = 2;
  run.band_angle_deg = -3.5;
  run.shape = "elliptical";
  StudyCaseResult c;
  c.summary = run;
  c.ensemble = make_ensemble({run});
  StudyRunResult replicate;
  replicate.summary = run;
  replicate.run_dir = "cases/all-step04/seed-2";
  c.runs.push_back(replicate);
  StudyReportInput in;
  in.study_name = "shortcuts";
  in.cases.push_back(c);
  return in;
}

}  // namespace

TEST(StudyReportCsv, ALabelWithCommasAndQuotesKeepsEveryColumnInPlace) {
  for (const std::string label : {"RF1", "all shortcuts, step fraction 0.4", "the \"fast\" rain, 2 layers"}) {
    const StudyReportInput in = one_case_labelled(label);
    for (const std::string& text : {metrics_csv(in), case_summary_csv(in)}) {
      const auto rows = read_csv(text);
      ASSERT_GE(rows.size(), 2u) << text;
      const std::vector<std::string>& header = rows.front();
      ASSERT_EQ(header[1], "label");
      for (std::size_t r = 1; r < rows.size(); ++r) {
        ASSERT_EQ(rows[r].size(), header.size()) << label << ": row " << r << " of\n" << text;
        EXPECT_EQ(rows[r][0], "all-step04");
        EXPECT_EQ(rows[r][1], label);
      }
    }
  }
}

TEST(StudyReportCsv, MetricsRowsCarryTheSeedAndTheValues) {
  const auto rows = read_csv(metrics_csv(one_case_labelled("all shortcuts, step fraction 0.4")));
  ASSERT_EQ(rows.size(), 2u);
  const std::vector<std::string>& header = rows[0];
  auto column = [&](const std::string& key) {
    for (std::size_t k = 0; k < header.size(); ++k)
      if (header[k] == key) return rows[1][k];
    ADD_FAILURE() << "no column " << key;
    return std::string();
  };
  EXPECT_EQ(column("seed"), "2");
  EXPECT_EQ(column("band_angle_deg"), "-3.5");
  EXPECT_EQ(column("shape"), "elliptical");
}
