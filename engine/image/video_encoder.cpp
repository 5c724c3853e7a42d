#include "engine/image/video_encoder.h"

#include "lsystem/common/output_file.h"
#include "lsystem/common/subprocess.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <stdexcept>
#include <string_view>

namespace pf {
namespace {

// ffmpeg's own limits: it holds a few frames and the encoder's look-ahead,
// well under 4 GiB of address space at 4K; a day of wall and CPU time.
lsys::ProcessLimits ffmpegLimits() {
    lsys::ProcessLimits limits;
    limits.maxMemoryBytes = size_t(4) << 30;
    limits.timeoutSeconds = 24 * 3600;
    return limits;
}

std::string fpsText(double fps) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", fps);
    return text;
}

// The last lines of ffmpeg's error output, for a message.
std::string ffmpegSays(const lsys::ProcessResult& result) {
    std::string text = result.failure.empty() ? result.err : result.failure;
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
    constexpr size_t kTail = 600;
    if (text.size() > kTail) text = "…" + text.substr(text.size() - kTail);
    return text.empty() ? "exit status " + std::to_string(result.exitCode) : text;
}

} // namespace

std::optional<std::string> videoMuxerFor(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".mp4") return "mp4";
    if (extension == ".mkv") return "matroska";
    if (extension == ".mov") return "mov";
    return std::nullopt;
}

VideoEncoder::VideoEncoder(const std::filesystem::path& path, uint32_t width, uint32_t height, double fps)
    : path_(path), width_(width), height_(height) {
    const std::optional<std::string> muxer = videoMuxerFor(path);
    if (!muxer)
        throw std::runtime_error("video " + path.string() + ": unknown extension '" + path.extension().string() +
                                 "' (expected .mp4, .mkv or .mov)");
    file_ = std::make_unique<lsys::OutputFile>(path);
    // yuv420p, the chroma layout every player decodes, needs even sizes: an
    // odd width or height is padded by one row or column. bitexact leaves
    // ffmpeg's version out of the file, so the same frames give the same bytes.
    const std::vector<std::string> argv{"ffmpeg",
                                        "-hide_banner",
                                        "-loglevel",
                                        "error",
                                        "-y",
                                        "-f",
                                        "rawvideo",
                                        "-pix_fmt",
                                        "rgba",
                                        "-video_size",
                                        std::to_string(width) + "x" + std::to_string(height),
                                        "-framerate",
                                        fpsText(fps),
                                        "-i",
                                        "pipe:0",
                                        "-vf",
                                        "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                                        "-c:v",
                                        "libx264",
                                        "-crf",
                                        "18",
                                        "-pix_fmt",
                                        "yuv420p",
                                        "-fflags",
                                        "+bitexact",
                                        "-flags:v",
                                        "+bitexact",
                                        "-f",
                                        *muxer,
                                        file_->temporaryPath().string()};
    ffmpeg_ = std::make_unique<lsys::Process>(argv, ffmpegLimits());
    if (!ffmpeg_->started())
        throw std::runtime_error("video " + path.string() + ": " + ffmpegSays(ffmpeg_->finish()) +
                                 " (install ffmpeg, or write PNG frames with --out-dir)");
}

VideoEncoder::~VideoEncoder() = default;

void VideoEncoder::addFrame(const RgbaImage& frame) {
    if (!ffmpeg_) throw std::logic_error("VideoEncoder::addFrame after finish");
    if (frame.width != width_ || frame.height != height_)
        throw std::runtime_error("video " + path_.string() + ": a frame of " + std::to_string(frame.width) + "x" +
                                 std::to_string(frame.height) + " in a video of " + std::to_string(width_) + "x" +
                                 std::to_string(height_));
    const std::string_view bytes(reinterpret_cast<const char*>(frame.pixels.data()), frame.pixels.size());
    if (!ffmpeg_->write(bytes))
        throw std::runtime_error("video " + path_.string() + ": ffmpeg stopped: " + ffmpegSays(ffmpeg_->finish()));
}

void VideoEncoder::finish() {
    if (!ffmpeg_) throw std::logic_error("VideoEncoder::finish twice");
    const lsys::ProcessResult result = ffmpeg_->finish();
    if (!result.failure.empty() || result.exitCode != 0)
        throw std::runtime_error("video " + path_.string() + ": ffmpeg failed: " + ffmpegSays(result));
    ffmpeg_.reset();
    file_->commit();
}

} // namespace pf
