// svg_picture.cpp: an SVG document drawn by librsvg and encoded as a PNG.
#include "report/svg_picture.hpp"

#include "report/native_library.hpp"

#include "assess/support/error.hpp"

#include <cairo.h>
#include <librsvg/rsvg.h>
#include <zlib.h>

#include <cstdint>
#include <cstring>

namespace assess::detail {

namespace {

// The functions of librsvg (and of cairo and GLib, which it loads), looked up once.
struct Librsvg {
  NativeLibrary lib{"librsvg-2.so.2", "librsvg2-2"};
  decltype(&::rsvg_handle_new_from_data) new_from_data = ASSESS_NATIVE(lib, rsvg_handle_new_from_data);
  decltype(&::rsvg_handle_get_intrinsic_dimensions) intrinsic_dimensions =
      ASSESS_NATIVE(lib, rsvg_handle_get_intrinsic_dimensions);
  decltype(&::rsvg_handle_render_document) render_document = ASSESS_NATIVE(lib, rsvg_handle_render_document);
  decltype(&::g_object_unref) object_unref = ASSESS_NATIVE(lib, g_object_unref);
  decltype(&::g_error_free) error_free = ASSESS_NATIVE(lib, g_error_free);
  decltype(&::cairo_image_surface_create) surface_create = ASSESS_NATIVE(lib, cairo_image_surface_create);
  decltype(&::cairo_surface_status) surface_status = ASSESS_NATIVE(lib, cairo_surface_status);
  decltype(&::cairo_surface_flush) surface_flush = ASSESS_NATIVE(lib, cairo_surface_flush);
  decltype(&::cairo_surface_destroy) surface_destroy = ASSESS_NATIVE(lib, cairo_surface_destroy);
  decltype(&::cairo_image_surface_get_data) surface_data = ASSESS_NATIVE(lib, cairo_image_surface_get_data);
  decltype(&::cairo_image_surface_get_stride) surface_stride = ASSESS_NATIVE(lib, cairo_image_surface_get_stride);
  decltype(&::cairo_create) create = ASSESS_NATIVE(lib, cairo_create);
  decltype(&::cairo_destroy) destroy = ASSESS_NATIVE(lib, cairo_destroy);
  decltype(&::cairo_set_source_rgb) set_source_rgb = ASSESS_NATIVE(lib, cairo_set_source_rgb);
  decltype(&::cairo_paint) paint = ASSESS_NATIVE(lib, cairo_paint);
};

struct Zlib {
  NativeLibrary lib{"libz.so.1", "zlib1g"};
  decltype(&::compress2) compress = ASSESS_NATIVE(lib, compress2);
  decltype(&::compressBound) bound = ASSESS_NATIVE(lib, compressBound);
  decltype(&::crc32) crc = ASSESS_NATIVE(lib, crc32);
};

const Librsvg& librsvg(const std::string& what) {
  static Librsvg r;
  r.lib.require(what);
  return r;
}

const Zlib& zlib(const std::string& what) {
  static Zlib z;
  z.lib.require(what);
  return z;
}

void put32(std::string& s, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) s += char((v >> shift) & 0xff);
}

// A PNG chunk: length, type, data, CRC of type and data (PNG spec., §5.3).
void chunk(std::string& png, const char* type, const std::string& data, const Zlib& z) {
  put32(png, std::uint32_t(data.size()));
  const std::string body = type + data;
  png += body;
  put32(png, std::uint32_t(z.crc(0, reinterpret_cast<const Bytef*>(body.data()), uInt(body.size()))));
}

}  // namespace

struct SvgPicture::Handle {
  const Librsvg& r;
  RsvgHandle* h;
  ~Handle() { r.object_unref(h); }
};

SvgPicture::SvgPicture(const std::string& svg, const std::string& what) : what_(what) {
  const Librsvg& r = librsvg(what);
  const auto begin = svg.find("<svg");
  const std::string doc = begin == std::string::npos ? svg : svg.substr(begin);
  GError* e = nullptr;
  RsvgHandle* h = r.new_from_data(reinterpret_cast<const guint8*>(doc.data()), doc.size(), &e);
  if (!h) {
    const std::string reason = e ? e->message : "unknown reason";
    if (e) r.error_free(e);
    throw InputError(what + ": librsvg cannot read a figure's SVG: " + reason);
  }
  handle_.reset(new Handle{r, h});
  gboolean has_w = false, has_h = false, has_box = false;
  RsvgLength w{}, hh{};
  RsvgRectangle box{};
  r.intrinsic_dimensions(h, &has_w, &w, &has_h, &hh, &has_box, &box);
  if (has_box && box.width > 0 && box.height > 0) aspect_ = box.height / box.width;
  else if (has_w && has_h && w.length > 0 && hh.length > 0 && w.unit == hh.unit) aspect_ = hh.length / w.length;
  else throw InputError(what + ": a figure's SVG has neither a viewBox nor a width and height");
}

SvgPicture::~SvgPicture() = default;

std::string SvgPicture::png(int width, int height) const {
  const Librsvg& r = handle_->r;
  const Zlib& z = zlib(what_);
  cairo_surface_t* s = r.surface_create(CAIRO_FORMAT_RGB24, width, height);
  std::unique_ptr<cairo_surface_t, decltype(r.surface_destroy)> surface(s, r.surface_destroy);
  cairo_t* cr = r.create(s);
  r.set_source_rgb(cr, 1, 1, 1);
  r.paint(cr);
  const RsvgRectangle viewport{0, 0, double(width), double(height)};
  GError* e = nullptr;
  const bool drawn = r.render_document(handle_->h, cr, &viewport, &e);
  r.destroy(cr);
  std::string reason = e ? e->message : "";
  if (e) r.error_free(e);
  if (!drawn || r.surface_status(s) != CAIRO_STATUS_SUCCESS)
    throw InputError(what_ + ": librsvg cannot draw a figure" + (reason.empty() ? "" : ": " + reason));
  r.surface_flush(s);
  // Rows of RGB bytes, each after its filter byte 0 (none), from cairo's native-endian 0x00RRGGBB words.
  const unsigned char* data = r.surface_data(s);
  const int stride = r.surface_stride(s);
  std::string raw(std::size_t(height) * (1 + 3 * std::size_t(width)), '\0');
  char* out = raw.data();
  for (int y = 0; y < height; ++y) {
    *out++ = 0;
    const unsigned char* row = data + std::size_t(y) * std::size_t(stride);
    for (int x = 0; x < width; ++x) {
      std::uint32_t p;
      std::memcpy(&p, row + 4 * x, 4);
      *out++ = char((p >> 16) & 0xff);
      *out++ = char((p >> 8) & 0xff);
      *out++ = char(p & 0xff);
    }
  }
  uLongf size = z.bound(uLong(raw.size()));
  std::string zipped(size, '\0');
  if (z.compress(reinterpret_cast<Bytef*>(zipped.data()), &size, reinterpret_cast<const Bytef*>(raw.data()),
                 uLong(raw.size()), 1) != Z_OK)
    throw InputError(what_ + ": zlib cannot compress a figure's PNG");
  zipped.resize(size);
  // PNG: signature, IHDR (width, height, 8-bit RGB, deflate, adaptive filtering, no interlace), IDAT, IEND.
  std::string ihdr;
  put32(ihdr, std::uint32_t(width));
  put32(ihdr, std::uint32_t(height));
  ihdr += std::string("\x08\x02\x00\x00\x00", 5);
  std::string png("\x89PNG\r\n\x1a\n", 8);
  chunk(png, "IHDR", ihdr, z);
  chunk(png, "IDAT", zipped, z);
  chunk(png, "IEND", "", z);
  return png;
}

}  // namespace assess::detail
