#include "display_image.h"

#include "film/accumulation_buffer.h"

namespace strata::viewer {

double pixelStandardError(const AccumulationBuffer& buffer, size_t pixel, bool stratified) {
    return stratified ? buffer.passStandardError(pixel) : buffer.sampleStandardError(pixel);
}

DisplayImage DisplayImage::fromBuffer(const AccumulationBuffer& buffer, bool stratified,
                                      const std::vector<uint8_t>* done) {
    DisplayImage image;
    image.width = buffer.width();
    image.height = buffer.height();
    const size_t pixels = buffer.pixelCount();
    image.meanAndCount.resize(4 * pixels);
    image.errorAndDone.resize(2 * pixels);
    for (size_t p = 0; p < pixels; ++p) {
        const glm::dvec3 mean = buffer.mean(p);
        image.meanAndCount[4 * p + 0] = static_cast<float>(mean.x);
        image.meanAndCount[4 * p + 1] = static_cast<float>(mean.y);
        image.meanAndCount[4 * p + 2] = static_cast<float>(mean.z);
        image.meanAndCount[4 * p + 3] = static_cast<float>(buffer.sampleCount(p));
        const double y = luminance(mean);
        image.errorAndDone[2 * p + 0] =
            y > 0.0 ? static_cast<float>(pixelStandardError(buffer, p, stratified) / y) : 0.0f;
        image.errorAndDone[2 * p + 1] = done && (*done)[p] ? 1.0f : 0.0f;
    }
    return image;
}

Image DisplayImage::radiance() const {
    Image image{width, height, {}};
    image.pixels.resize(static_cast<size_t>(width) * height);
    for (size_t p = 0; p < image.pixels.size(); ++p) {
        image.pixels[p] = glm::vec3(meanAndCount[4 * p], meanAndCount[4 * p + 1], meanAndCount[4 * p + 2]);
    }
    return image;
}

}  // namespace strata::viewer
