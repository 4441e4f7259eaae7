// ProgressReporter: quiet mode, throttling of a non-terminal output, and the final line.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "io/progress.hpp"

namespace rfmems {
namespace {

// Everything written to f so far.
std::string contents(std::FILE* f) {
  std::fflush(f);
  std::rewind(f);
  std::string s;
  for (int c; (c = std::fgetc(f)) != EOF;) s += static_cast<char>(c);
  return s;
}

TEST(Progress, QuietPrintsNothing) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    ProgressReporter p(true, 1.0, f);
    p.update(0.5, 0.01, 50);
    p.finish();
  }
  EXPECT_EQ(contents(f), "");
  std::fclose(f);
}

TEST(Progress, LogGetsNoLineBeforeFiveSecondsThenOneFinalLine) {
  std::FILE* f = std::tmpfile();  // not a terminal
  ASSERT_NE(f, nullptr);
  ProgressReporter p(false, 2e-5, f);
  for (long i = 1; i <= 100; ++i) p.update(1e-7 * static_cast<double>(i), 1e-7, i);
  EXPECT_EQ(contents(f), "");  // far less than 5 s have passed
  p.finish();
  p.finish();  // a second call adds nothing
  const std::string out = contents(f);
  EXPECT_NE(out.find("t = 1e-05 s / 2e-05 s (50.0%)"), std::string::npos) << out;
  EXPECT_NE(out.find("h = 1e-07 s"), std::string::npos) << out;
  EXPECT_NE(out.find("steps 100"), std::string::npos) << out;
  EXPECT_NE(out.find("elapsed "), std::string::npos) << out;
  EXPECT_EQ(out.find('\r'), std::string::npos) << out;
  EXPECT_EQ(out.back(), '\n');
  EXPECT_EQ(out.find('\n'), out.size() - 1) << out;  // exactly one line
  std::fclose(f);
}

}  // namespace
}  // namespace rfmems
