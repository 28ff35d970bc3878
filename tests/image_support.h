#pragma once
// Image files written in code for the tests of the readers (io/texture_image.h, io/exr_header.h):
// small valid ones of each format, and forged or truncated ones whose headers claim more pixels
// than the file holds, as a fuzzer or a cut download makes them. No binary files in the tree.
#include <string>
#include <vector>

namespace strata::test {

// A PNG of `width` x `height` pixels of `bitDepth` bits, colour type `colourType` (0 grey, 2 RGB,
// 4 grey-alpha, 6 RGBA), from its filtered rows (each a filter byte 0 and the packed samples),
// deflated as stored blocks; `chunksBeforeData` (whole chunks, see pngChunk) go before IDAT.
std::string pngFile(int width, int height, int bitDepth, int colourType, const std::string& rows,
                    const std::string& chunksBeforeData = "");
// One PNG chunk: length, type, data and CRC.
std::string pngChunk(const std::string& type, const std::string& data);
// A PNG header claiming `width` x `height` pixels of `bitDepth` bits and `colourType`, with
// `dataBytes` bytes of image data that are no deflate stream.
std::string forgedPng(int width, int height, int bitDepth, int colourType, size_t dataBytes);

// A GIF of one image of `width` x `height` palette indices (row-major) into a palette of 4
// colours: black, white, red, green.
std::string gifFile(int width, int height, const std::vector<unsigned char>& indices);
// A GIF whose screen and first image claim `width` x `height` pixels, with `dataBytes` bytes of
// image data (about 40 KB for the 16384 x 16384 of a fuzzer's finding).
std::string forgedGif(int width, int height, size_t dataBytes);

// A JPEG (libjpeg, quality 90; baseline or progressive) of `channels` 1 or 3 of 8-bit pixels.
std::string jpegFile(int width, int height, int channels, const std::vector<unsigned char>& pixels,
                     bool progressive = false);
// A 32 x 32 RGB JPEG cut in the middle of its coded data and closed with an end-of-image marker,
// as a truncated file "repaired": stb_image decoded it without a word.
std::string truncatedJpeg();
// A JPEG of noise whose frame header is made to claim `width` x `height` pixels, cut to
// `totalBytes` bytes and closed with an end-of-image marker, as a truncated file "repaired".
std::string forgedJpeg(int width, int height, size_t totalBytes);

// An uncompressed scanline EXR header of `width` x `height` float RGB pixels and its table of
// chunk offsets, one a line, pointing where the lines would be: the file ends there, without
// any pixel data (93 KB for 23170 x 11585).
std::string forgedExr(int width, int height);

}  // namespace strata::test
