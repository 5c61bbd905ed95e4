#include "reports/annual_results.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/error.h"
#include "sample_report.h"

namespace candela {
namespace {

namespace fs = std::filesystem;

AnnualResults sample(int sensors, bool leap) {
  AnnualResults r;
  r.sensors = sensors;
  r.hours = testing_sample::sampleYearStamps(leap);
  const std::size_t n = r.hours.size();
  for (int s = 0; s < sensors; ++s)
    for (std::size_t h = 0; h < n; ++h) r.lux.push_back(static_cast<float>(s * 1000.0 + h * 0.25));  // exact in float32
  return r;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

uint32_t u32(const std::string& b, std::size_t at) {
  uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= static_cast<uint32_t>(static_cast<unsigned char>(b[at + i])) << (8 * i);
  return v;
}

TEST(AnnualResults, RoundTripsValuesAndStamps) {
  const AnnualResults r = sample(3, true);
  ASSERT_EQ(r.hours.size(), 8784u);
  const fs::path path = fs::path(testing::TempDir()) / "candela_annual" / annualResultsFileName("Work plane");
  EXPECT_EQ(path.filename().string(), "Work_plane_hourly.f32");
  writeAnnualResults(path, r);
  const AnnualResults back = readAnnualResults(path);
  EXPECT_EQ(back.sensors, 3);
  EXPECT_EQ(back.hours, r.hours);
  EXPECT_EQ(back.lux, r.lux);  // float32 both ways: bit exact
  EXPECT_FLOAT_EQ(back.at(2, 100), 2025.0f);
  const std::vector<double> series = back.sensorSeries(1);
  ASSERT_EQ(series.size(), 8784u);
  EXPECT_DOUBLE_EQ(series[8783], 1000.0 + 8783 * 0.25);
}

// The byte layout documented in the header and docs/annual-outputs.md, read back by hand.
TEST(AnnualResults, SizesAndLayoutAsDocumented) {
  const AnnualResults r = sample(2, false);
  const std::string b = encodeAnnualResults(r);
  const std::size_t nH = 8760, nS = 2;
  EXPECT_EQ(b.size(), 48 + 4 * nH + 4 * nS * nH);
  EXPECT_EQ(b.substr(0, 8), "CNDLHRLY");
  EXPECT_EQ(u32(b, 8), 1u);
  EXPECT_EQ(u32(b, 12), 48 + 4 * nH);
  EXPECT_EQ(u32(b, 16), nS);
  EXPECT_EQ(u32(b, 20), nH);
  EXPECT_EQ(std::string(b.c_str() + 24), "sensor-major");
  EXPECT_EQ(std::string(b.c_str() + 40), "lux");
  // Last stamp: 31 December, hour ending 24.
  EXPECT_EQ(static_cast<int>(b[48 + 4 * (nH - 1)]), 12);
  EXPECT_EQ(static_cast<int>(b[48 + 4 * (nH - 1) + 1]), 31);
  EXPECT_EQ(static_cast<int>(b[48 + 4 * (nH - 1) + 2]), 24);
  // Sensor-major: value(1, 3) at index 1·nH + 3 of the float block, IEEE-754 little-endian.
  float v;
  const uint32_t bits = u32(b, 48 + 4 * nH + 4 * (nH + 3));
  std::memcpy(&v, &bits, 4);
  EXPECT_EQ(v, 1000.0f + 3 * 0.25f);

  AnnualResults bad = r;
  bad.lux.pop_back();
  EXPECT_THROW(encodeAnnualResults(bad), std::invalid_argument);
}

TEST(AnnualResults, CallbackWriterMatchesStructWriter) {
  const AnnualResults r = sample(2, false);
  const fs::path dir = fs::path(testing::TempDir()) / "candela_annual_cb";
  // Values held hour-major by the caller are still written sensor-major.
  std::vector<float> hourMajor(r.lux.size());
  for (int s = 0; s < 2; ++s)
    for (int h = 0; h < 8760; ++h) hourMajor[static_cast<std::size_t>(h) * 2 + s] = r.at(s, h);
  writeAnnualResults(dir / "cb.f32", 2, r.hours,
                     [&](int s, int h) { return hourMajor[static_cast<std::size_t>(h) * 2 + s]; });
  EXPECT_EQ(slurp(dir / "cb.f32"), encodeAnnualResults(r));
}

std::string errorOf(const std::string& bytes) {
  try {
    decodeAnnualResults(bytes, "grid_hourly.f32");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(AnnualResults, TruncatedFileIsAnInputErrorWithTheByteOffset) {
  const std::string b = encodeAnnualResults(sample(2, false));
  const std::string cut = b.substr(0, b.size() - 2);
  const std::string msg = errorOf(cut);
  EXPECT_EQ(msg.rfind("grid_hourly.f32: byte " + std::to_string(cut.size()) + ": truncated file", 0), 0u) << msg;
  EXPECT_NE(errorOf(b.substr(0, 20)).find("truncated header"), std::string::npos);
  EXPECT_NE(errorOf(b + "xx").find("file too long"), std::string::npos);
}

TEST(AnnualResults, BadMagicVersionAndSizesAreInputErrors) {
  const std::string good = encodeAnnualResults(sample(1, false));
  std::string b = good;
  b[0] = 'X';
  EXPECT_EQ(errorOf(b).rfind("grid_hourly.f32: byte 0: not a candela hourly results file", 0), 0u) << errorOf(b);
  b = good;
  b[8] = 2;
  EXPECT_NE(errorOf(b).find("byte 8: unsupported version 2"), std::string::npos) << errorOf(b);
  b = good;
  b[16] = 2;  // claims 2 sensors: the data block is then half missing
  EXPECT_NE(errorOf(b).find("truncated file"), std::string::npos) << errorOf(b);
  b = good;
  b[20] = static_cast<char>(b[20] + 1);  // one more hour than the data offset allows
  EXPECT_NE(errorOf(b).find("byte 12: data offset"), std::string::npos) << errorOf(b);
  b = good;
  b[24] = 'h';
  EXPECT_NE(errorOf(b).find("byte 24: unknown layout"), std::string::npos) << errorOf(b);
  b = good;
  b[48] = 13;  // month 13
  EXPECT_NE(errorOf(b).find("byte 48: hour 0 has an invalid stamp"), std::string::npos) << errorOf(b);
  EXPECT_THROW(readAnnualResults(fs::path(testing::TempDir()) / "no_such_dir" / "x.f32"), InputError);
}

// The streaming writer (a study's blocks) against the one-call encoder of the same values.
TEST(AnnualResultsStream, RowsAppendedInBlocksGiveTheEncodedBytes) {
  const AnnualResults r = sample(7, false);
  const fs::path dir = fs::path(testing::TempDir()) / "candela_annual_stream";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path path = dir / "grid_hourly.f32";
  {
    AnnualResultsStream stream(path, 7, r.hours);
    const float* rows = r.lux.data();
    for (int count : {3, 0, 1, 3}) {
      stream.append(rows, count);
      rows += static_cast<std::size_t>(count) * 8760;
    }
    EXPECT_EQ(stream.written(), 7);
    // Rows already written read back as they went in (the blinds' second pass).
    std::vector<float> back(2 * 8760);
    stream.read(4, 2, back.data());
    EXPECT_TRUE(std::equal(back.begin(), back.end(), r.lux.begin() + 4 * 8760));
    EXPECT_THROW(stream.read(6, 2, back.data()), std::invalid_argument);
    EXPECT_THROW(stream.append(rows, 1), std::invalid_argument);  // an eighth sensor
    EXPECT_FALSE(fs::exists(path));  // nothing under the name until the stream is committed
    stream.commitAs(path);
    EXPECT_THROW(stream.append(rows, 0), std::invalid_argument);  // committed: finished
  }
  EXPECT_EQ(slurp(path), encodeAnnualResults(r));
}

TEST(AnnualResultsStream, AnUnfinishedStreamLeavesNoFile) {
  const AnnualResults r = sample(3, false);
  const fs::path dir = fs::path(testing::TempDir()) / "candela_annual_unfinished";
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    AnnualResultsStream stream(dir / "a.f32", 3, r.hours);
    stream.append(r.lux.data(), 2);
    EXPECT_THROW(stream.commitAs(dir / "a.f32"), std::invalid_argument);  // a row missing: never a whole file
  }
  EXPECT_FALSE(fs::exists(dir / "a.f32"));
  {
    AnnualResultsStream stream(dir / "b.f32", 3, r.hours);
    stream.append(r.lux.data(), 1);
  }  // destroyed mid-way (a failed run)
  EXPECT_TRUE(fs::is_empty(dir));
}

// Committing replaces whatever has the name, a planted link included, and never writes through it.
TEST(AnnualResultsStream, CommitReplacesANameOrLinkWithoutWritingThroughIt) {
  const AnnualResults r = sample(1, false);
  const fs::path dir = fs::path(testing::TempDir()) / "candela_annual_excl";
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    std::ofstream(dir / "victim") << "keep";
    std::ofstream(dir / "there.f32") << "old";
  }
  fs::create_symlink(dir / "victim", dir / "link.f32");
  for (const char* name : {"link.f32", "there.f32"}) {
    AnnualResultsStream stream(dir / name, 1, r.hours);
    stream.append(r.lux.data(), 1);
    stream.commitAs(dir / name);
    EXPECT_FALSE(fs::is_symlink(fs::symlink_status(dir / name))) << name;
    EXPECT_EQ(slurp(dir / name), encodeAnnualResults(r)) << name;
  }
  EXPECT_EQ(slurp(dir / "victim"), "keep");
}

// The index of the file is its fixed row size: a sensor range read at its offset.
TEST(AnnualResults, RowsReadAtTheirOffsetAreThoseOfTheWholeFile) {
  const AnnualResults r = sample(5, true);
  const fs::path path = fs::path(testing::TempDir()) / "candela_annual_rows" / "rows.f32";
  writeAnnualResults(path, r);
  const AnnualResults rows = readAnnualResultsRows(path, 2, 2);
  EXPECT_EQ(rows.sensors, 2);
  EXPECT_EQ(rows.hours, r.hours);
  ASSERT_EQ(rows.lux.size(), 2u * 8784);
  EXPECT_EQ(rows.sensorSeries(0), r.sensorSeries(2));
  EXPECT_EQ(rows.sensorSeries(1), r.sensorSeries(3));
  EXPECT_EQ(readAnnualResultsRows(path, 5, 0).lux.size(), 0u);
  EXPECT_THROW(readAnnualResultsRows(path, 4, 2), InputError);
  EXPECT_THROW(readAnnualResultsRows(path, -1, 1), InputError);
  // The whole header is checked, the file's size included.
  const std::string b = slurp(path);
  std::ofstream(path, std::ios::binary) << b.substr(0, b.size() - 4);
  EXPECT_THROW(readAnnualResultsRows(path, 0, 1), InputError);
}

}  // namespace
}  // namespace candela
