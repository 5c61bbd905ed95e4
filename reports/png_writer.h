// PNG output (libpng, 8-bit RGB) and false-colour images with a legend drawn in.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "base/atomic_file.h"
#include "reports/falsecolor.h"

namespace candela {

// 8-bit sRGB image, rows top to bottom, 3 bytes per pixel.
struct Image8 {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;
  Image8() = default;
  Image8(int w, int h, Rgb8 fill = {255, 255, 255});
  void set(int x, int y, Rgb8 c);  // ignores pixels outside the image
  Rgb8 at(int x, int y) const;
  void fillRect(int x, int y, int w, int h, Rgb8 c);
};

// Draws `text` with candela's 5×7 pixel font (digits, ". - + e % / space" and the letters of
// "lx cd/m k": enough for legend numbers and units), each font pixel `scale`×`scale` image
// pixels, top-left corner at (x, y). Unknown characters draw as a hollow box.
void drawText(Image8& image, int x, int y, const std::string& text, Rgb8 color, int scale = 1);

// Width in pixels of `text` drawn at `scale` (6 font pixels per character, no trailing gap).
int textWidth(const std::string& text, int scale = 1);

// A picture made a row at a time, for pictures too large to hold: row(y, out) fills
// out[0 .. 3 · width) with row y's 8-bit RGB. What it reads must outlive it.
struct RowPicture {
  int width = 0, height = 0;
  std::function<void(int y, uint8_t* rgb)> row;
};
RowPicture rowsOf(const Image8& image);  // `image` must outlive the result
Image8 imageOf(const RowPicture& picture);

// The picture of falseColorImage, row by row (its legend strip drawn once); `values` must
// outlive it.
RowPicture falseColorRows(const std::vector<float>& values, int width, int height, const ColorScale& scale,
                          const std::string& unit);

// A false-colour picture of `values` (row-major, `width` × `height`, top row first) with a
// legend to the right: colour bar, tick values and the unit.
Image8 falseColorImage(const std::vector<float>& values, int width, int height, const ColorScale& scale,
                       const std::string& unit);

// PNG bytes of the image (8-bit RGB, no interlace).
std::vector<uint8_t> encodePng(const Image8& image);

// RFC 4648 base64 of `bytes`, for embedding PNG pictures as data URIs in the report and plans.
std::string base64(const std::vector<uint8_t>& bytes);

// Writes the image as a PNG, atomically, a row at a time (no encoded copy in memory). Throws std::runtime_error on failure.
void writePng(const std::filesystem::path& path, const Image8& image);
// A picture into `out` a row at a time, left uncommitted (its caller commits it).
void writePng(AtomicFile& out, const RowPicture& picture);

}  // namespace candela
