// VideoEncoder (engine/image/video_encoder.h): frames in, a video ffprobe
// reads back at the right size, count and colours; bad extensions, wrong
// frame sizes and a failing ffmpeg leave an existing file as it was.
#include "engine/image/video_encoder.h"

#include "run_command.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace pf {
namespace {

namespace fs = std::filesystem;
using test::runCommand;

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::path(PLANTFIELD_TEST_OUTPUT_DIR) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

RgbaImage solid(uint32_t width, uint32_t height, uint8_t r, uint8_t g, uint8_t b) {
    RgbaImage image{width, height, {}};
    for (uint32_t i = 0; i < width * height; ++i) image.pixels.insert(image.pixels.end(), {r, g, b, 255});
    return image;
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// Five frames of an odd size in five colours: ffprobe counts five frames
// padded to the even size yuv420p needs, and frame 3 decodes to its colour
// within H.264's loss.
TEST(VideoEncoder, WritesTheFramesFfmpegReadsBack) {
    ASSERT_EQ(runCommand("command -v ffmpeg").exitCode, 0) << "ffmpeg is missing: run tools/deps.sh";
    const fs::path video = scratch("frames") / "clip.mp4";
    const uint8_t colors[5][3] = {{200, 30, 30}, {30, 200, 30}, {30, 30, 200}, {220, 220, 40}, {40, 200, 200}};
    {
        VideoEncoder encoder(video, 33, 21, 24.0);
        for (const auto& c : colors) encoder.addFrame(solid(33, 21, c[0], c[1], c[2]));
        encoder.finish();
    }
    const test::CommandResult probe = runCommand(
        "ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=width,height,nb_read_frames,"
        "codec_name,r_frame_rate -of csv=p=0 " +
        video.string());
    ASSERT_EQ(probe.exitCode, 0) << probe.output;
    EXPECT_EQ(probe.output, "h264,34,22,24/1,5\n");

    const fs::path raw = video.parent_path() / "frame3.rgba";
    const test::CommandResult decode =
        runCommand("ffmpeg -v error -i " + video.string() +
                   " -vf 'select=eq(n\\,3)' -frames:v 1 -f rawvideo -pix_fmt rgba " + raw.string());
    ASSERT_EQ(decode.exitCode, 0) << decode.output;
    const std::string pixels = readFile(raw);
    ASSERT_EQ(pixels.size(), 34u * 22u * 4u);
    const size_t centre = (11 * 34 + 16) * 4;
    for (int channel = 0; channel < 3; ++channel)
        EXPECT_NEAR(uint8_t(pixels[centre + channel]), colors[3][channel], 6) << "channel " << channel;
}

// Same frames, same bytes: ffmpeg's version and the time are left out.
TEST(VideoEncoder, TheSameFramesGiveTheSameFile) {
    const fs::path dir = scratch("same");
    for (const char* name : {"a.mkv", "b.mkv"}) {
        VideoEncoder encoder(dir / name, 16, 16, 30.0);
        for (uint8_t i = 0; i < 4; ++i) encoder.addFrame(solid(16, 16, uint8_t(40 * i), 90, 160));
        encoder.finish();
    }
    EXPECT_EQ(readFile(dir / "a.mkv"), readFile(dir / "b.mkv"));
}

TEST(VideoEncoder, RefusesUnknownExtensionsAndWrongFrameSizes) {
    const fs::path dir = scratch("refused");
    try {
        VideoEncoder encoder(dir / "clip.gif", 16, 16, 30.0);
        FAIL() << "a .gif was accepted";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("unknown extension '.gif' (expected .mp4, .mkv or .mov)"),
                  std::string::npos)
            << error.what();
    }
    VideoEncoder encoder(dir / "clip.mp4", 16, 16, 30.0);
    EXPECT_THROW(encoder.addFrame(solid(8, 16, 0, 0, 0)), std::runtime_error);
}

// ffmpeg refuses a frame rate of 0: the message is ffmpeg's, and the file
// that was there stays, as does a video never finished.
TEST(VideoEncoder, AFailedEncodingLeavesTheExistingFile) {
    const fs::path dir = scratch("failed");
    const fs::path video = dir / "clip.mp4";
    std::ofstream(video) << "an earlier video";
    try {
        VideoEncoder encoder(video, 16, 16, 0.0);
        encoder.addFrame(solid(16, 16, 1, 2, 3));
        encoder.finish();
        FAIL() << "a frame rate of 0 was encoded";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("video " + video.string()), std::string::npos) << error.what();
    }
    {
        VideoEncoder unfinished(video, 16, 16, 30.0);
        unfinished.addFrame(solid(16, 16, 1, 2, 3));
    }
    EXPECT_EQ(readFile(video), "an earlier video");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1) << "a temporary file is left";
}

} // namespace
} // namespace pf
