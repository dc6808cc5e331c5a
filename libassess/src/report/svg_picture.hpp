// svg_picture.hpp (private to the report layer): a figure's SVG document as a
// picture for the Word writer: its aspect (the viewBox's) and a PNG of it at
// a given size, drawn by librsvg on a white ground (Debian package
// librsvg2-2, loaded when first used: native_library.hpp) and encoded with
// zlib (fast deflate, no filter: a tenth of cairo's own PNG writer's time for
// the same picture). Word 2016 and later show the SVG; the PNG is the
// fallback every .docx reader can show.
#pragma once

#include <memory>
#include <string>

namespace assess::detail {

class SvgPicture {
 public:
  /// Parses `svg` (an SVG document, its XML prolog allowed). InputError
  /// naming `what` when librsvg is missing or cannot read it.
  SvgPicture(const std::string& svg, const std::string& what);
  ~SvgPicture();
  SvgPicture(const SvgPicture&) = delete;
  SvgPicture& operator=(const SvgPicture&) = delete;

  /// Height over width of the picture: its viewBox's, else its width and height's.
  double aspect() const { return aspect_; }

  /// The picture as a PNG of `width` x `height` pixels (RGB, white ground).
  std::string png(int width, int height) const;

 private:
  struct Handle;
  std::unique_ptr<Handle> handle_;
  std::string what_;
  double aspect_ = 0.0;
};

}  // namespace assess::detail
