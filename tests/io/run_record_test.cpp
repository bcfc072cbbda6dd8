// run.json is always JSON: non-finite numbers become null and are named in "non_finite",
// wherever they sit (a top-level key, a nested table, an array, an array of arrays).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "mpmx/io/run_record.hpp"
#include "strict_json.hpp"

using mpmx::io::RunRecord;
using mpmx::test::StrictJson;

namespace {
const double kNan = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

bool is_json(const std::string& s, std::string& why) {
  StrictJson j(s);
  const bool ok = j.valid();
  why = j.error();
  return ok;
}
}  // namespace

TEST(StrictJson, RefusesWhatNoJsonReaderAccepts) {
  std::string why;
  EXPECT_TRUE(is_json(R"({"a" : [1, -2.5e3, null, "x"], "b" : {"c" : true}})", why)) << why;
  EXPECT_FALSE(is_json(R"({"a" : nan})", why));
  EXPECT_FALSE(is_json(R"({"a" : -nan})", why));
  EXPECT_FALSE(is_json(R"({"a" : inf})", why));
  EXPECT_FALSE(is_json(R"({"a" : [1, 2,]})", why));
}

TEST(RunRecord, NonFiniteNumbersAreNullAndNamed) {
  RunRecord rec;
  rec.set("status", "stopped");
  rec.set("time", kNan);
  rec.set("conservation.energy.error", -kInf);
  rec.set("conservation.mass.nodes", 1.5);
  rec.set("profile", std::vector<double>{1.0, kInf, 3.0});
  toml::table box{{"lx", kNan}, {"ly", 2.0}};
  box.insert("stress", toml::array{toml::array{1.0, kNan}, toml::array{-kInf, 4.0}});
  rec.set("box", std::move(box));
  const std::string json = rec.json();
  std::string why;
  ASSERT_TRUE(is_json(json, why)) << why << "\n" << json;
  EXPECT_EQ(json.find("nan"), std::string::npos) << json;
  EXPECT_EQ(json.find("inf"), std::string::npos) << json;
  EXPECT_NE(json.find("\"time\" : null"), std::string::npos) << json;
  EXPECT_NE(json.find("\"error\" : null"), std::string::npos) << json;
  EXPECT_NE(json.find("\"nodes\" : 1.5"), std::string::npos) << json;
  EXPECT_NE(json.find("\"lx\" : null"), std::string::npos) << json;
  // The keys of the nulls, in order.
  for (const char* key : {"\"box.lx\"", "\"box.stress[0][1]\"", "\"box.stress[1][0]\"",
                          "\"conservation.energy.error\"", "\"profile[1]\"", "\"time\""})
    EXPECT_NE(json.find(key), std::string::npos) << key << "\n" << json;
  EXPECT_NE(json.find("\"non_finite\""), std::string::npos) << json;
  // The record itself keeps the values (a checkpoint's TOML can hold them).
  EXPECT_TRUE(std::isnan(rec.table()["time"].value<double>().value()));
}

TEST(RunRecord, AllFiniteHasNoNonFiniteList) {
  RunRecord rec;
  rec.set("time", 2.0);
  rec.set("steps", std::int64_t{10});
  const std::string json = rec.json();
  std::string why;
  EXPECT_TRUE(is_json(json, why)) << why;
  EXPECT_EQ(json.find("non_finite"), std::string::npos) << json;
  EXPECT_NE(json.find("\"time\" : 2.0"), std::string::npos) << json;
}

TEST(RunRecord, WrittenFileIsJson) {
  RunRecord rec;
  rec.set("errors.velocity.l1", kNan);
  const std::string path = ::testing::TempDir() + "run_record_test.json";
  rec.write(path);
  std::FILE* f = std::fopen(path.c_str(), "r");
  ASSERT_NE(f, nullptr);
  std::string text;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) text.append(buf, n);
  std::fclose(f);
  std::string why;
  EXPECT_TRUE(is_json(text, why)) << why << "\n" << text;
  EXPECT_NE(text.find("\"errors.velocity.l1\""), std::string::npos) << text;
}
