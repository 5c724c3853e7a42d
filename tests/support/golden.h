// Golden-image comparison for render tests, after Filament's render-diff
// tests: a per-channel tolerance and a fraction of pixels allowed to exceed
// it. On failure the actual image and a difference image are written next to
// the test binary. Goldens are rewritten only when PLANTFIELD_UPDATE_GOLDENS=1.
#pragma once

#include "engine/image/image.h"

#include <gtest/gtest.h>

#include <string>

namespace pf::test {

struct ImageTolerance {
    int channel = 5;                     // largest allowed |actual - expected| per channel, in 1/255
    double failingPixelFraction = 0.001; // pixels allowed beyond `channel`
};

struct ImageDiff {
    bool sameSize = false;
    uint64_t failingPixels = 0; // pixels with any channel beyond the tolerance
    double failingFraction = 0.0;
    int maxChannelDelta = 0;
    double psnr = 0.0; // dB over RGB; infinity when identical
};

ImageDiff compareImages(const RgbaImage& actual, const RgbaImage& expected, int channelTolerance);
// Red where a pixel fails, a dimmed grey copy of the expected image elsewhere.
RgbaImage makeDiffImage(const RgbaImage& actual, const RgbaImage& expected, int channelTolerance);

// Compares with tests/golden/<name>.png. Writes <name>-actual.png and
// <name>-diff.png into `outputDir` on failure.
::testing::AssertionResult matchesGolden(const RgbaImage& actual, const std::string& name,
                                         const ImageTolerance& tolerance, const std::string& goldenDir,
                                         const std::string& outputDir);

} // namespace pf::test
