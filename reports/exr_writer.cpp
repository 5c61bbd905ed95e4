#include "reports/exr_writer.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>

#include <atomic>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

namespace candela {

void writeLuminanceExr(const std::filesystem::path& path, int width, int height,
                       const std::vector<double>& luminance, const std::vector<Rgb>& rgb, const std::string& comment) {
  const std::size_t n = static_cast<std::size_t>(width) * height;
  if (width <= 0 || height <= 0 || luminance.size() != n || (!rgb.empty() && rgb.size() != n))
    throw std::invalid_argument("writeLuminanceExr: need width × height values");
  std::vector<float> y(n), r, g, b;
  for (std::size_t i = 0; i < n; ++i) y[i] = static_cast<float>(luminance[i]);
  if (!rgb.empty()) {
    r.resize(n);
    g.resize(n);
    b.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      r[i] = static_cast<float>(rgb[i].x);
      g[i] = static_cast<float>(rgb[i].y);
      b[i] = static_cast<float>(rgb[i].z);
    }
  }

  Imf::Header header(width, height);
  header.compression() = Imf::ZIP_COMPRESSION;
  header.insert(kExrUnitAttribute, Imf::StringAttribute(kExrLuminanceUnit));
  Imf::addWhiteLuminance(header, 1.0f);
  if (!comment.empty()) Imf::addComments(header, comment);
  Imf::FrameBuffer fb;
  const std::size_t xs = sizeof(float), ys = sizeof(float) * static_cast<std::size_t>(width);
  auto add = [&](const char* name, std::vector<float>& v) {
    header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    fb.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(v.data()), xs, ys));
  };
  add("Y", y);
  if (!rgb.empty()) {
    add("R", r);
    add("G", g);
    add("B", b);
  }

  // A temporary beside the target (same file system, so the rename is atomic).
  static std::atomic<unsigned> counter{0};
  std::filesystem::path tmp = path;
  tmp += ".tmp" + std::to_string(::getpid()) + "_" + std::to_string(counter.fetch_add(1));
  try {
    {
      Imf::OutputFile file(tmp.string().c_str(), header);
      file.setFrameBuffer(fb);
      file.writePixels(height);
    }
    std::filesystem::rename(tmp, path);
  } catch (const std::exception& e) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw std::runtime_error("cannot write " + path.string() + ": " + e.what());
  }
}

}  // namespace candela
