#include "jpeg.h"

#include <csetjmp>
#include <cstdio>
#include <limits>

// jpeglib.h uses size_t and FILE without including their headers.
#include <jpeglib.h>

namespace facet::runtime {
namespace {

// libjpeg reports errors through a callback that must not return: it jumps back to the call
// that started the work. Nothing between that call and libjpeg has a destructor to skip.
struct ErrorManager {
  jpeg_error_mgr base;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

[[noreturn]] void onError(j_common_ptr info) {
  auto* manager = reinterpret_cast<ErrorManager*>(info->err);
  manager->base.format_message(info, manager->message);
  std::longjmp(manager->jump, 1);
}

// A warning (level -1) is data libjpeg could not read and decoded around: a cut or corrupt
// entropy-coded segment becomes grey blocks. A texture that is silently part grey is a wrong
// result, so a warning fails the decode like an error. Trace messages (level >= 0) are ignored.
void onMessage(j_common_ptr info, int level) {
  if (level < 0) onError(info);
}

// A progressive file may hold any number of scans, each refining every coefficient of the image:
// a few kilobytes of tiny scans cost seconds of work each time the image is decoded. Encoders
// write at most a few dozen (libjpeg's default script is 10 for colour); 500 is the limit
// libjpeg-turbo's own decompression API and its fuzzers use for the same reason.
constexpr int kMaxProgressiveScans = 500;

void onProgress(j_common_ptr info) {
  auto* decompress = reinterpret_cast<j_decompress_ptr>(info);
  if (decompress->progressive_mode && decompress->input_scan_number > kMaxProgressiveScans) {
    auto* manager = reinterpret_cast<ErrorManager*>(info->err);
    std::snprintf(manager->message, sizeof manager->message,
                  "a progressive JPEG of more than %d scans (the limit; encoders write a few dozen)",
                  kMaxProgressiveScans);
    std::longjmp(manager->jump, 2);
  }
}

// The most memory libjpeg may allocate for one image: a progressive image keeps every DCT
// coefficient (2 bytes) of every component until its last scan, 3 components × 2 bytes × 8192²
// pixels (kMaxImageSide) = 384 MiB, plus block padding and its small tables.
constexpr long kMaxDecoderBytes = 448L << 20;

struct Decoder {
  jpeg_decompress_struct info{};
  ErrorManager errors{};
  jpeg_progress_mgr progress{};

  Decoder() {
    info.err = jpeg_std_error(&errors.base);
    errors.base.error_exit = onError;
    errors.base.emit_message = onMessage;
    progress.progress_monitor = onProgress;
  }
  ~Decoder() { jpeg_destroy_decompress(&info); }
};

// Starts a decompression and reads the header; the caller has set the jump target.
void readHeader(Decoder& d, std::span<const uint8_t> bytes) {
  jpeg_create_decompress(&d.info);
  d.info.progress = &d.progress;
  d.info.mem->max_memory_to_use = kMaxDecoderBytes;
  jpeg_mem_src(&d.info, bytes.data(), static_cast<unsigned long>(bytes.size()));
  jpeg_read_header(&d.info, TRUE);
}

std::string colourSpaceError(const jpeg_decompress_struct& info) {
  if (info.jpeg_color_space == JCS_CMYK || info.jpeg_color_space == JCS_YCCK)
    return "a CMYK JPEG (textures are greyscale or colour JPEGs)";
  if (info.num_components != 1 && info.num_components != 3)
    return "a JPEG of " + std::to_string(info.num_components) + " components (1 or 3 are read)";
  return "";
}

bool tooLarge(std::span<const uint8_t> bytes, std::string* why) {
  if (bytes.size() <= std::numeric_limits<unsigned long>::max()) return false;
  *why = "the file is larger than libjpeg reads";
  return true;
}

}  // namespace

bool isJpeg(std::span<const uint8_t> bytes) {
  return bytes.size() >= 3 && bytes[0] == 0xff && bytes[1] == 0xd8 && bytes[2] == 0xff;
}

bool probeJpeg(std::span<const uint8_t> bytes, int* width, int* height, std::string* why) {
  if (tooLarge(bytes, why)) return false;
  Decoder d;
  if (setjmp(d.errors.jump)) {
    *why = d.errors.message;
    return false;
  }
  readHeader(d, bytes);
  *why = colourSpaceError(d.info);
  *width = int(d.info.image_width);  // at most 65535 (16-bit fields in the frame header)
  *height = int(d.info.image_height);
  return why->empty();
}

bool decodeJpeg(std::span<const uint8_t> bytes, std::vector<uint8_t>* rgba, int* width, int* height, std::string* why) {
  if (tooLarge(bytes, why)) return false;
  Decoder d;
  if (setjmp(d.errors.jump)) {
    *why = d.errors.message;
    return false;
  }
  readHeader(d, bytes);
  *why = colourSpaceError(d.info);
  if (!why->empty()) return false;
  // libjpeg-turbo's extended colour space: RGBA straight from YCbCr, RGB or greyscale.
  d.info.out_color_space = JCS_EXT_RGBA;
  jpeg_start_decompress(&d.info);
  *width = int(d.info.output_width);
  *height = int(d.info.output_height);
  const size_t stride = size_t(d.info.output_width) * 4;
  rgba->assign(stride * d.info.output_height, 0);
  while (d.info.output_scanline < d.info.output_height) {
    JSAMPROW row = rgba->data() + stride * d.info.output_scanline;
    jpeg_read_scanlines(&d.info, &row, 1);
  }
  jpeg_finish_decompress(&d.info);
  return true;
}

}  // namespace facet::runtime
