// Declared portals: `[[portal]]` in a case and `--portal` files (study/case/portal_file.h), their
// errors at the offending line, and both reaching the scene the tracer sees.
#include "study/case/case_file.h"
#include "study/case/case_scene.h"
#include "study/points_study.h"
#include "study/case/portal_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace candela {
namespace {

namespace fs = std::filesystem;

// The InputError's line and a piece of its message; fails when the text is accepted.
void expectCaseError(const std::string& text, int line, const std::string& words) {
  try {
    parseCaseFile(text, "/tmp/portal_case.toml");
    FAIL() << "accepted:\n" << text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, line) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("portal_case.toml:" + std::to_string(line) + ": "), std::string::npos)
        << e.what();
  }
}

TEST(PortalTable, ReadsOutlineAndName) {
  const CaseFile c = parseCaseFile("[[portal]]\n"
                                   "name = \"skylight\"\n"
                                   "outline = [[1, 1, 3], [2, 1, 3], [2, 2, 3], [1, 2, 3]]\n"
                                   "[[portal]]\n"
                                   "outline = [[0, 0, 1], [0, 1, 1], [0, 1, 2]]\n",
                                   "/tmp/portal_case.toml");
  ASSERT_EQ(c.portals.size(), 2u);
  EXPECT_EQ(c.portals[0].name, "skylight");
  EXPECT_EQ(c.portals[0].outline.size(), 4u);
  EXPECT_EQ(c.portals[0].outline[2], Vec3(2, 2, 3));
  EXPECT_EQ(c.portals[1].name, "portal2");
  EXPECT_EQ(c.portals[0].loc.line, 1);
  // They reach the scene.
  const auto scene = loadCaseScene(c, false);
  EXPECT_EQ(scene->portals.size(), 2u);
}

TEST(PortalTable, ErrorsNameTheLineOfTheBadVertex) {
  expectCaseError("[[portal]]\n"
                  "outline = [\n"
                  "  [1, 1, 3],\n"
                  "  [2, 1],\n"
                  "  [2, 2, 3]]\n",
                  4, "'outline' must be an array of 3 numbers [x, y, z]");
  expectCaseError("[[portal]]\n"
                  "outline = [\n"
                  "  [1, 1, 3],\n"
                  "  [2, 1, 3],\n"
                  "  [2, 2, 3],\n"
                  "  [1, 2, 3.5]]\n",
                  6, "portal vertex 4 lies 0.5 m off the plane of the first three");
  expectCaseError("[[portal]]\noutline = [[1, 1, 3], [2, 1, 3]]\n", 2, "at least 3 vertices, got 2");
  expectCaseError("[[portal]]\noutline = [[1, 1, 3], [2, 1, 3], [3, 1, 3]]\n", 2, "encloses no area");
  expectCaseError("[[portal]]\nvertices = [[1, 1, 3], [2, 1, 3], [2, 2, 3]]\n", 1, "needs the key 'outline'");
  expectCaseError("[[portal]]\noutline = [[1, 1, 3], [2, 1, 3], [2, 2, 3]]\nglass = true\n", 3,
                  "unknown key 'glass' in [[portal]]");
}

TEST(PortalFile, OnePolygonPerLineWithErrorsAtTheirLine) {
  const std::vector<Portal> ps = parsePortals("# openings\n"
                                              "\n"
                                              "1 1 3  2 1 3  2 2 3  1 2 3   # skylight\n"
                                              "0 0 1  0 1 1  0 1 2\n",
                                              "open.txt");
  ASSERT_EQ(ps.size(), 2u);
  EXPECT_EQ(ps[0].outline.size(), 4u);
  EXPECT_EQ(ps[1].outline[2], Vec3(0, 1, 2));
  EXPECT_EQ(ps[1].loc.line, 4);
  auto lineOf = [](const std::string& text, const std::string& words) {
    try {
      parsePortals(text, "open.txt");
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind("open.txt:", 0), 0u) << e.what();
      return e.loc().line;
    }
    return 0;
  };
  EXPECT_EQ(lineOf("1 1 3  2 1 3  2 2 3\n1 1 3  2 x 3  2 2 3\n", "'x' is not a number"), 2);
  EXPECT_EQ(lineOf("\n\n1 1 3  2 1 3  2 2\n", "not a whole number of vertices"), 3);
  EXPECT_EQ(lineOf("1 1 3  2 1 3\n", "at least 3 vertices"), 1);
  EXPECT_EQ(lineOf("1 1 3  2 1 3  2 2 3  1 2 4\n", "off the plane of the first three"), 1);
}

TEST(PortalFile, PointsJobAddsThemToTheScene) {
  const fs::path dir = fs::temp_directory_path() / "candela-portal-test";
  fs::create_directories(dir);
  const fs::path file = dir / "portals.txt";
  std::ofstream(file) << "-0.5 -0.75 3  0.5 -0.75 3  0.5 0.75 3  -0.5 0.75 3\n";
  PointsJob job;
  job.portalFiles = {file};
  const PointsScene s = loadPointsScene(job);
  ASSERT_EQ(s.scene->portals.size(), 1u);
  EXPECT_EQ(s.scene->portals[0].outline[1], Vec3(0.5, -0.75, 3));
  job.portalFiles = {dir / "no_such.txt"};
  EXPECT_THROW(loadPointsScene(job), InputError);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace candela
