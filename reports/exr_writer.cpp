#include "reports/exr_writer.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>

#include "base/atomic_file.h"

#include <cstring>
#include <stdexcept>

namespace candela {

namespace {

// The file's bytes in memory, so that they reach the disk through writeFileAtomic (an exclusive
// temporary, never through a link) like every other output.
class MemoryStream : public Imf::OStream {
 public:
  MemoryStream() : Imf::OStream("memory") {}
  void write(const char c[], int n) override {
    if (pos_ + n > bytes_.size()) bytes_.resize(pos_ + n);
    std::memcpy(bytes_.data() + pos_, c, static_cast<std::size_t>(n));
    pos_ += static_cast<std::size_t>(n);
  }
  uint64_t tellp() override { return pos_; }
  void seekp(uint64_t pos) override { pos_ = static_cast<std::size_t>(pos); }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
  std::size_t pos_ = 0;
};

}  // namespace

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

  MemoryStream stream;
  try {
    Imf::OutputFile file(stream, header);
    file.setFrameBuffer(fb);
    file.writePixels(height);
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot write " + path.string() + ": " + e.what());
  }
  writeFileAtomic(path, stream.bytes());
}

}  // namespace candela
