#include "reports/exr_writer.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>

#include "base/atomic_file.h"

#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <cstring>
#include <unistd.h>
#include <stdexcept>

namespace candela {

namespace {

// The file as OpenEXR writes it: straight into an exclusive temporary (AtomicFile), so that a
// large image never sits in memory encoded; OpenEXR seeks back once to write its line offsets.
class FileStream : public Imf::OStream {
 public:
  explicit FileStream(AtomicFile& file) : Imf::OStream("exr"), file_(file) {}
  void write(const char c[], int n) override {
    try {
      file_.write(std::string_view(c, static_cast<std::size_t>(n)));
    } catch (const std::exception& e) {
      failure_ = e.what();
      throw;
    }
  }
  // What went wrong, if anything: OpenEXR's destructor writes the line offsets and swallows
  // an error there.
  const std::string& failure() const { return failure_; }
  uint64_t tellp() override { return static_cast<uint64_t>(::lseek(file_.descriptor(), 0, SEEK_CUR)); }
  void seekp(uint64_t pos) override {
    if (::lseek(file_.descriptor(), static_cast<off_t>(pos), SEEK_SET) < 0)
      throw std::runtime_error(std::string("cannot seek: ") + std::strerror(errno));
  }

 private:
  AtomicFile& file_;
  std::string failure_;
};

// Scanlines converted and written per block of this many rows (16 KiB a row at 8192 px).
constexpr int kRowsPerBlock = 64;

}  // namespace

void writeLuminanceExr(AtomicFile& out, const std::string& name, int width, int height,
                       const std::vector<float>& luminance, const std::vector<glm::vec3>& rgb, double rgbScale,
                       const std::string& comment) {
  const std::size_t n = static_cast<std::size_t>(width) * height;
  if (width <= 0 || height <= 0 || luminance.size() != n || (!rgb.empty() && rgb.size() != n))
    throw std::invalid_argument("writeLuminanceExr: need width × height values");
  Imf::Header header(width, height);
  header.compression() = Imf::ZIP_COMPRESSION;
  header.insert(kExrUnitAttribute, Imf::StringAttribute(kExrLuminanceUnit));
  Imf::addWhiteLuminance(header, 1.0f);
  if (!comment.empty()) Imf::addComments(header, comment);
  const int channels = rgb.empty() ? 1 : 4;
  for (const char* channel : {"Y", "R", "G", "B"}) {
    header.channels().insert(channel, Imf::Channel(Imf::FLOAT));
    if (channels == 1) break;
  }
  // One block of rows at a time: Y, R, G, B interleaved per pixel.
  std::vector<float> block(static_cast<std::size_t>(width) * kRowsPerBlock * channels);
  const std::size_t xs = sizeof(float) * channels, ys = xs * static_cast<std::size_t>(width);
  try {
    FileStream stream(out);
    {
      Imf::OutputFile file(stream, header);
      for (int y0 = 0; y0 < height; y0 += kRowsPerBlock) {
        const int rows = std::min(kRowsPerBlock, height - y0);
        for (std::size_t k = 0; k < static_cast<std::size_t>(rows) * width; ++k) {
          const std::size_t i = static_cast<std::size_t>(y0) * width + k;
          float* p = block.data() + k * channels;
          p[0] = luminance[i];
          if (channels == 1) continue;
          for (int c = 0; c < 3; ++c) p[1 + c] = static_cast<float>(rgbScale * static_cast<double>(rgb[i][c]));
        }
        // The frame buffer's origin is row 0: the block's pointer less y0 rows.
        char* base = reinterpret_cast<char*>(block.data()) - static_cast<std::ptrdiff_t>(y0) * static_cast<std::ptrdiff_t>(ys);
        Imf::FrameBuffer fb;
        const char* names[] = {"Y", "R", "G", "B"};
        for (int c = 0; c < channels; ++c)
          fb.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xs, ys));
        file.setFrameBuffer(fb);
        file.writePixels(rows);
      }
    }
    if (!stream.failure().empty()) throw std::runtime_error(stream.failure());
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot write " + name + ": " + e.what());
  }
}

void writeLuminanceExr(const std::filesystem::path& path, int width, int height, const std::vector<float>& luminance,
                       const std::vector<glm::vec3>& rgb, double rgbScale, const std::string& comment) {
  // The sizes are checked before anything is written; a failure leaves the temporary to
  // AtomicFile's destructor, and its own messages name the file.
  AtomicFile out(path);
  writeLuminanceExr(out, path.string(), width, height, luminance, rgb, rgbScale, comment);
  out.commit();
}

}  // namespace candela
