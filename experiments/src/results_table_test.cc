#include "cogmap/experiments/results_table.h"

#include <gtest/gtest.h>

namespace cogmap::experiments {
namespace {

TEST(ResultsTable, FlattensMetricsInDocumentOrder) {
  const auto flat = flatten_metrics_json(
      R"({"asr_count": 9, "map": {"wall_error_median_m": 0.1, "wall_coverage": null},
          "rooms": [{"id": 0}], "ok": true, "localization": {"ate_rmse_m": {"odometry": 1.5}}})");
  const std::vector<std::pair<std::string, std::string>> expected{
      {"asr_count", "9"},
      {"map.wall_error_median_m", "0.1"},
      {"map.wall_coverage", ""},
      {"ok", "true"},
      {"localization.ate_rmse_m.odometry", "1.5"}};
  EXPECT_EQ(flat, expected);
}

TEST(ResultsTable, BuildWriteParseRoundTrip) {
  SweepRun a;
  a.index = 0;
  a.values = {{"mapper.waypoints", "[1, 2]"}};
  a.seed = 1;
  SweepRun b = a;
  b.index = 1;
  b.seed = 2;
  const ResultsTable t = build_results_table(
      {a, b}, {"mapper.waypoints"},
      {{{"asr_count", "2"}, {"x", "0.5"}}, {{"asr_count", "3"}, {"y", "say \"hi\""}}});
  EXPECT_EQ(t.header,
            (std::vector<std::string>{"run", "mapper.waypoints", "seed", "asr_count", "x", "y"}));
  EXPECT_EQ(t.rows[1], (std::vector<std::string>{"1", "[1, 2]", "2", "3", "", "say \"hi\""}));
  const std::string csv = to_csv(t);
  EXPECT_EQ(csv,
            "run,mapper.waypoints,seed,asr_count,x,y\n"
            "0,\"[1, 2]\",1,2,0.5,\n"
            "1,\"[1, 2]\",2,3,,\"say \"\"hi\"\"\"\n");
  const ResultsTable back = parse_csv(csv, "results.csv");
  EXPECT_EQ(back.header, t.header);
  EXPECT_EQ(back.rows, t.rows);
}

TEST(ResultsTable, MergeOrdersByRunAndChecksHeaders) {
  const ResultsTable s1 = parse_csv("run,seed,m\n0,1,0.5\n2,3,0.7\n", "s1");
  const ResultsTable s2 = parse_csv("run,seed,m\n1,2,0.6\n", "s2");
  const ResultsTable merged = merge_results({{"s1", s1}, {"s2", s2}});
  ASSERT_EQ(merged.rows.size(), 3u);
  EXPECT_EQ(to_csv(merged), "run,seed,m\n0,1,0.5\n1,2,0.6\n2,3,0.7\n");
  // The same run twice with the same content is harmless (a re-run shard).
  EXPECT_EQ(merge_results({{"s1", s1}, {"s1again", s1}}).rows.size(), 2u);

  const ResultsTable other = parse_csv("run,seed,n\n1,2,0.6\n", "other");
  try {
    (void)merge_results({{"s1", s1}, {"other", other}});
    FAIL() << "header mismatch accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("other: header differs"), std::string::npos);
  }
  const ResultsTable clash = parse_csv("run,seed,m\n0,1,0.9\n", "clash");
  EXPECT_THROW((void)merge_results({{"s1", s1}, {"clash", clash}}), std::runtime_error);
}

TEST(ResultsTable, RaggedCsvIsAnError) {
  EXPECT_THROW((void)parse_csv("run,seed\n1\n", "bad.csv"), std::runtime_error);
  EXPECT_THROW((void)parse_csv("", "empty.csv"), std::runtime_error);
}

std::string merge_error(const std::string& csv) {
  try {
    (void)merge_results({{"r.csv", parse_csv(csv, "r.csv")}});
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(ResultsTable, RowsKnowTheirLinesAndRunsMustBeIndices) {
  // A quoted field over two lines and a blank line: the third row starts on line 6.
  const std::string csv = "run,name\n0,\"two\nlines\"\n\n1,b\n-5,c\n";
  const ResultsTable t = parse_csv(csv, "r.csv");
  EXPECT_EQ(t.row_lines, (std::vector<int>{2, 5, 6}));
  EXPECT_EQ(merge_error(csv), "r.csv:6: run: '-5' is not a run index (a whole number, 0 or more)");
  EXPECT_EQ(merge_error("run,m\n0,1\nabc,2\n"),
            "r.csv:3: run: 'abc' is not a run index (a whole number, 0 or more)");
  EXPECT_EQ(merge_error("run,m\n0,1\n1.5,2\n"),
            "r.csv:3: run: '1.5' is not a run index (a whole number, 0 or more)");
  EXPECT_EQ(merge_error("run,m\n0,1\n7,2\n"), "");
  // A ragged row is named by its own line, not its record number.
  try {
    (void)parse_csv("run,m\n0,\"a\nb\"\n1\n", "bad.csv");
    FAIL() << "ragged row accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "bad.csv:4: expected 2 columns, got 1");
  }
}

}  // namespace
}  // namespace cogmap::experiments
