// The validation page: every case with its verdict and errors, failing cases opened, one
// self-contained file (no external references), names escaped.
#include "validation/validation_html.h"

#include <gtest/gtest.h>

#include <regex>

namespace candela::validation {
namespace {

TEST(ValidationHtml, ListsEveryCaseWithVerdictAndIsSelfContained) {
  CaseResult ok;
  ok.name = "sphere-source";
  ok.group = "engine";
  ok.reference = "E = pi L r^2 cos / d^2";
  ok.tolerance = 0.01;
  ok.points = {{"x=1 m", 100.0, 100.5, 0.2}};  // +0.5 %: pass
  CaseResult bad = ok;
  bad.name = "a<b";
  bad.points = {{"p", 100.0, 103.0, 1.0}};  // +3 %: fail
  ValidationPage page;
  page.quality = "normal";
  page.version = "0.1.0";
  page.chartSvg = "<svg id=\"chart\"></svg>";
  const std::string html = validationHtml({ok, bad}, page);
  EXPECT_NE(html.find("2 cases: 1 passed, 1 failed"), std::string::npos);
  EXPECT_NE(html.find("sphere-source"), std::string::npos);
  EXPECT_NE(html.find("a&lt;b"), std::string::npos);
  EXPECT_EQ(html.find("a<b"), std::string::npos);
  EXPECT_NE(html.find("0.500 %"), std::string::npos);   // max error of the passing case
  EXPECT_NE(html.find("3.000 %"), std::string::npos);   // and of the failing one
  EXPECT_NE(html.find("<details id=\"a&lt;b\" open>"), std::string::npos);  // failures shown open
  EXPECT_NE(html.find("<svg id=\"chart\">"), std::string::npos);
  EXPECT_FALSE(std::regex_search(html, std::regex(R"((src=|<link|<script|https?://))")));
}

}  // namespace
}  // namespace candela::validation
