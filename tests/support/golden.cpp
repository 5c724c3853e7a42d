#include "golden.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <sstream>

namespace pf::test {

ImageDiff compareImages(const RgbaImage& actual, const RgbaImage& expected, int channelTolerance) {
    ImageDiff diff;
    diff.sameSize = actual.width == expected.width && actual.height == expected.height &&
                    actual.pixels.size() == expected.pixels.size();
    if (!diff.sameSize) return diff;
    double squaredError = 0.0;
    const size_t pixelCount = size_t(actual.width) * actual.height;
    for (size_t p = 0; p < pixelCount; ++p) {
        int pixelMax = 0;
        for (int c = 0; c < 3; ++c) {
            const int d = std::abs(int(actual.pixels[p * 4 + c]) - int(expected.pixels[p * 4 + c]));
            pixelMax = std::max(pixelMax, d);
            squaredError += double(d) * d;
        }
        diff.maxChannelDelta = std::max(diff.maxChannelDelta, pixelMax);
        if (pixelMax > channelTolerance) ++diff.failingPixels;
    }
    diff.failingFraction = pixelCount ? double(diff.failingPixels) / double(pixelCount) : 0.0;
    const double mse = pixelCount ? squaredError / (3.0 * double(pixelCount)) : 0.0;
    diff.psnr = mse > 0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : std::numeric_limits<double>::infinity();
    return diff;
}

RgbaImage makeDiffImage(const RgbaImage& actual, const RgbaImage& expected, int channelTolerance) {
    RgbaImage out{expected.width, expected.height, std::vector<uint8_t>(expected.pixels.size())};
    for (size_t p = 0; p + 3 < expected.pixels.size(); p += 4) {
        int pixelMax = 0;
        for (int c = 0; c < 3; ++c)
            pixelMax = std::max(pixelMax, std::abs(int(actual.pixels[p + c]) - int(expected.pixels[p + c])));
        const uint8_t grey = uint8_t((expected.pixels[p] + expected.pixels[p + 1] + expected.pixels[p + 2]) / 12);
        const bool fails = pixelMax > channelTolerance;
        out.pixels[p] = fails ? 255 : grey;
        out.pixels[p + 1] = fails ? 0 : grey;
        out.pixels[p + 2] = fails ? 0 : grey;
        out.pixels[p + 3] = 255;
    }
    return out;
}

::testing::AssertionResult matchesGolden(const RgbaImage& actual, const std::string& name,
                                         const ImageTolerance& tolerance, const std::string& goldenDir,
                                         const std::string& outputDir) {
    namespace fs = std::filesystem;
    const std::string goldenPath = goldenDir + "/" + name + ".png";
    const char* update = std::getenv("PLANTFIELD_UPDATE_GOLDENS");
    if (update && std::strcmp(update, "1") == 0) {
        writePng(goldenPath, actual);
        return ::testing::AssertionSuccess() << "golden " << goldenPath << " rewritten";
    }
    if (!fs::exists(goldenPath))
        return ::testing::AssertionFailure()
               << "golden " << goldenPath << " is missing; create it with PLANTFIELD_UPDATE_GOLDENS=1";
    const RgbaImage expected = readPng(goldenPath);
    const ImageDiff diff = compareImages(actual, expected, tolerance.channel);
    std::ostringstream report;
    report << name << ": ";
    if (!diff.sameSize) {
        report << "size " << actual.width << "x" << actual.height << " differs from golden " << expected.width << "x"
               << expected.height;
    } else {
        report << diff.failingPixels << " pixels (" << diff.failingFraction * 100.0 << "%) differ by more than "
               << tolerance.channel << "/255, largest difference " << diff.maxChannelDelta << ", PSNR " << diff.psnr
               << " dB (allowed " << tolerance.failingPixelFraction * 100.0 << "%)";
    }
    if (diff.sameSize && diff.failingFraction <= tolerance.failingPixelFraction)
        return ::testing::AssertionSuccess() << report.str();

    fs::create_directories(outputDir);
    const std::string actualPath = outputDir + "/" + name + "-actual.png";
    writePng(actualPath, actual);
    report << "; wrote " << actualPath;
    if (diff.sameSize) {
        const std::string diffPath = outputDir + "/" + name + "-diff.png";
        writePng(diffPath, makeDiffImage(actual, expected, tolerance.channel));
        report << " and " << diffPath;
    }
    return ::testing::AssertionFailure() << report.str();
}

} // namespace pf::test
