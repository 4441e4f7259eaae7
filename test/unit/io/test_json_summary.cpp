// JSON summaries: text form and atomic writing.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/json_summary.hpp"

namespace rfmems {
namespace {

TEST(JsonSummary, TextIsIndentedWithFinalNewlineAndNoNaN) {
  Json j;
  j["status"] = "ok";
  j["tip_deflection"] = -1.5e-6;
  j["bad"] = std::nan("");
  const std::string text = json_text(j);
  EXPECT_EQ(text.back(), '\n');
  EXPECT_NE(text.find("\n  \"status\": \"ok\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"bad\": null"), std::string::npos) << text;
  EXPECT_NO_THROW(json_text(Json("\xff invalid utf-8")));
}

TEST(JsonSummary, WriteIsAtomicAndReadable) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("rfmems_json_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string path = (dir / "out" / "summary.json").string();  // parent created
  write_json_atomic(path, Json{{"steps", 12}, {"converged", true}});
  std::ifstream in(path);
  const Json back = Json::parse(in);
  EXPECT_EQ(back["steps"], 12);
  EXPECT_EQ(back["converged"], true);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir / "out"), fs::directory_iterator()),
            1);  // no temporary
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rfmems
