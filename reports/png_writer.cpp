#include "reports/png_writer.h"

#include <png.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string_view>

#include "base/atomic_file.h"
#include "reports/report_data.h"

namespace candela {

Image8::Image8(int w, int h, Rgb8 fill) : width(w), height(h), rgb(static_cast<std::size_t>(w) * h * 3) {
  for (std::size_t i = 0; i < rgb.size(); i += 3) {
    rgb[i] = fill.r;
    rgb[i + 1] = fill.g;
    rgb[i + 2] = fill.b;
  }
}

void Image8::set(int x, int y, Rgb8 c) {
  if (x < 0 || y < 0 || x >= width || y >= height) return;
  const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
  rgb[i] = c.r;
  rgb[i + 1] = c.g;
  rgb[i + 2] = c.b;
}

Rgb8 Image8::at(int x, int y) const {
  const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
  return {rgb[i], rgb[i + 1], rgb[i + 2]};
}

void Image8::fillRect(int x, int y, int w, int h, Rgb8 c) {
  for (int j = y; j < y + h; ++j)
    for (int i = x; i < x + w; ++i) set(i, j, c);
}

namespace {

// candela's own 5×7 font: each glyph is 7 rows of 5 columns, '#' = ink.
struct Glyph {
  char ch;
  std::array<std::string_view, 7> rows;
};

constexpr Glyph kFont[] = {
    {'0', {" ### ", "#   #", "#  ##", "# # #", "##  #", "#   #", " ### "}},
    {'1', {"  #  ", " ##  ", "  #  ", "  #  ", "  #  ", "  #  ", " ### "}},
    {'2', {" ### ", "#   #", "    #", "   # ", "  #  ", " #   ", "#####"}},
    {'3', {"#####", "   # ", "  #  ", "   # ", "    #", "#   #", " ### "}},
    {'4', {"   # ", "  ## ", " # # ", "#  # ", "#####", "   # ", "   # "}},
    {'5', {"#####", "#    ", "#### ", "    #", "    #", "#   #", " ### "}},
    {'6', {"  ## ", " #   ", "#    ", "#### ", "#   #", "#   #", " ### "}},
    {'7', {"#####", "    #", "   # ", "  #  ", " #   ", " #   ", " #   "}},
    {'8', {" ### ", "#   #", "#   #", " ### ", "#   #", "#   #", " ### "}},
    {'9', {" ### ", "#   #", "#   #", " ####", "    #", "   # ", " ##  "}},
    {'.', {"     ", "     ", "     ", "     ", "     ", " ##  ", " ##  "}},
    {'-', {"     ", "     ", "     ", "#####", "     ", "     ", "     "}},
    {'+', {"     ", "  #  ", "  #  ", "#####", "  #  ", "  #  ", "     "}},
    {'e', {"     ", "     ", " ### ", "#   #", "#####", "#    ", " ### "}},
    {'k', {"#    ", "#    ", "#  # ", "# #  ", "##   ", "# #  ", "#  # "}},
    {'l', {" ##  ", "  #  ", "  #  ", "  #  ", "  #  ", "  #  ", " ### "}},
    {'x', {"     ", "     ", "#   #", " # # ", "  #  ", " # # ", "#   #"}},
    {'c', {"     ", "     ", " ### ", "#    ", "#    ", "#   #", " ### "}},
    {'d', {"    #", "    #", " ## #", "#  ##", "#   #", "#   #", " ####"}},
    {'m', {"     ", "     ", "## # ", "# # #", "# # #", "#   #", "#   #"}},
    {'/', {"     ", "    #", "   # ", "  #  ", " #   ", "#    ", "     "}},
    {'%', {"##   ", "##  #", "   # ", "  #  ", " #   ", "#  ##", "   ##"}},
    {' ', {"     ", "     ", "     ", "     ", "     ", "     ", "     "}},
};

constexpr Glyph kUnknown = {'?', {"#####", "#   #", "#   #", "#   #", "#   #", "#   #", "#####"}};

const Glyph& glyphFor(char c) {
  for (const Glyph& g : kFont)
    if (g.ch == c) return g;
  return kUnknown;
}

// Where libpng's bytes go: a vector, or a file being written (an error there is kept and
// reported through png_error, which longjmps back: no C++ exception crosses libpng's C frames).
struct PngSink {
  std::vector<uint8_t>* bytes = nullptr;
  AtomicFile* file = nullptr;
  std::string error;
};

void sinkBytes(png_structp png, png_bytep data, png_size_t length) {
  auto* sink = static_cast<PngSink*>(png_get_io_ptr(png));
  if (sink->bytes) {
    sink->bytes->insert(sink->bytes->end(), data, data + length);
    return;
  }
  try {
    sink->file->write(std::string_view(reinterpret_cast<const char*>(data), length));
  } catch (const std::exception& e) {
    sink->error = e.what();
    png_error(png, "write failed");
  }
}

void flushNothing(png_structp) {}

// 8-bit RGB, no interlace, sRGB chunk; a row at a time into `sink`.
void encodePngTo(const RowPicture& image, PngSink& sink) {
  std::vector<uint8_t> row(static_cast<std::size_t>(image.width) * 3);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (!png) throw std::runtime_error("libpng: cannot create write struct");
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error(sink.error.empty() ? "libpng: encoding failed" : sink.error);
  }
  png_set_write_fn(png, &sink, sinkBytes, flushNothing);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y) {
    image.row(y, row.data());
    png_write_row(png, row.data());
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
}

}  // namespace

int textWidth(const std::string& text, int scale) {
  return text.empty() ? 0 : (static_cast<int>(text.size()) * 6 - 1) * scale;
}

void drawText(Image8& image, int x, int y, const std::string& text, Rgb8 color, int scale) {
  for (std::size_t k = 0; k < text.size(); ++k) {
    const Glyph& g = glyphFor(text[k]);
    const int gx = x + static_cast<int>(k) * 6 * scale;
    for (int row = 0; row < 7; ++row)
      for (int col = 0; col < 5; ++col)
        if (g.rows[row][col] == '#') image.fillRect(gx + col * scale, y + row * scale, scale, scale, color);
  }
}

RowPicture rowsOf(const Image8& image) {
  return RowPicture{image.width, image.height, [&image](int y, uint8_t* out) {
                      const std::size_t n = static_cast<std::size_t>(image.width) * 3;
                      std::copy_n(image.rgb.data() + static_cast<std::size_t>(y) * n, n, out);
                    }};
}

Image8 imageOf(const RowPicture& picture) {
  Image8 img(picture.width, picture.height);
  for (int y = 0; y < picture.height; ++y)
    picture.row(y, img.rgb.data() + static_cast<std::size_t>(y) * picture.width * 3);
  return img;
}

RowPicture falseColorRows(const std::vector<float>& values, int width, int height, const ColorScale& scale,
                          const std::string& unit) {
  if (width <= 0 || height <= 0 || values.size() != static_cast<std::size_t>(width) * height)
    throw std::invalid_argument("falseColorImage: need width × height values");
  // Legend font size follows the picture so it stays legible on large renderings.
  const int fs = std::max(1, height / 240);
  const std::vector<double> ticks = scaleTicks(scale, 6);
  int labelWidth = textWidth(unit, fs);
  for (double t : ticks) labelWidth = std::max(labelWidth, textWidth(formatNumber(t, 4), fs));
  const int pad = 6 * fs, barWidth = 14 * fs;
  const int legendWidth = pad + barWidth + 3 * fs + labelWidth + pad;
  // The legend strip right of the picture, drawn once (a few MB at 8192 px high).
  auto legend = std::make_shared<Image8>(legendWidth, height, Rgb8{255, 255, 255});
  // Colour bar: bottom = scale minimum, top = maximum, between a unit label and the tick labels.
  const Rgb8 ink{40, 40, 40};
  const int barX = pad, barTop = pad + 12 * fs, barBottom = height - pad - 4 * fs;
  drawText(*legend, barX, pad, unit, ink, fs);
  if (barBottom > barTop) {
    for (int y = barTop; y <= barBottom; ++y) {
      const double t = static_cast<double>(barBottom - y) / (barBottom - barTop);
      legend->fillRect(barX, y, barWidth, 1, viridis(t));
    }
    for (double v : ticks) {
      const int y = barBottom - static_cast<int>(std::lround(scalePosition(v, scale) * (barBottom - barTop)));
      legend->fillRect(barX + barWidth, y, 2 * fs, fs, ink);
      drawText(*legend, barX + barWidth + 3 * fs, y - 3 * fs, formatNumber(v, 4), ink, fs);
    }
  }
  return RowPicture{width + legendWidth, height, [&values, width, scale, legend](int y, uint8_t* out) {
                      for (int x = 0; x < width; ++x) {
                        const Rgb8 c = falseColor(values[static_cast<std::size_t>(y) * width + x], scale);
                        out[3 * x] = c.r;
                        out[3 * x + 1] = c.g;
                        out[3 * x + 2] = c.b;
                      }
                      const std::size_t n = static_cast<std::size_t>(legend->width) * 3;
                      std::copy_n(legend->rgb.data() + static_cast<std::size_t>(y) * n, n, out + 3 * width);
                    }};
}

Image8 falseColorImage(const std::vector<float>& values, int width, int height, const ColorScale& scale,
                       const std::string& unit) {
  return imageOf(falseColorRows(values, width, height, scale, unit));
}

std::string base64(const std::vector<uint8_t>& bytes) {
  static const char* kTable = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const uint32_t b0 = bytes[i], b1 = i + 1 < bytes.size() ? bytes[i + 1] : 0, b2 = i + 2 < bytes.size() ? bytes[i + 2] : 0;
    const uint32_t v = (b0 << 16) | (b1 << 8) | b2;
    out += kTable[(v >> 18) & 63];
    out += kTable[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kTable[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kTable[v & 63] : '=';
  }
  return out;
}

std::vector<uint8_t> encodePng(const Image8& image) {
  std::vector<uint8_t> out;
  PngSink sink;
  sink.bytes = &out;
  encodePngTo(rowsOf(image), sink);
  return out;
}

void writePng(AtomicFile& out, const RowPicture& picture) {
  PngSink sink;
  sink.file = &out;
  encodePngTo(picture, sink);
}

void writePng(const std::filesystem::path& path, const Image8& image) {
  AtomicFile file(path);
  writePng(file, rowsOf(image));
  file.commit();
}

}  // namespace candela
