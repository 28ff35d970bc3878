#pragma once
// An EXR file's header, read and checked against the file before anything is allocated for its
// pixels (OpenEXR's C core, which reads the header and the chunk table without decoding).
//
// A header's data window alone says nothing of whether the file holds those pixels: a forged or
// truncated file of some kilobytes can claim 23170 x 11585 float pixels, which OpenEXR's reader
// would allocate (3 GB) before failing at the first missing chunk. Every chunk of the first
// part's full-resolution pixels must therefore lie within the file, its recorded size included.
#include <string>
#include <string_view>

#include "textures/texture.h"

namespace strata {

// Whether `bytes` begin with OpenEXR's magic number.
bool isExr(std::string_view bytes);

// The size of the R, G, B float image readExr (io/image_io.h) reads from the EXR file `bytes`
// (3 channels of 4 bytes). Throws strata::Error: "NAME: not a readable EXR file (REASON)" for
// bytes OpenEXR cannot read, a deep image or pixel data the file does not hold, and
// requirePlausibleImageSize's error (io/image_io.h) for an implausible size.
TextureSize readExrHeader(std::string_view bytes, const std::string& name);

}  // namespace strata
