// A video file written frame by frame through ffmpeg (plantfield --video):
// RGBA frames go to ffmpeg's standard input as raw video and come out as
// H.264 (yuv420p, CRF 18) in an MP4, Matroska or QuickTime file, chosen by
// the extension. ffmpeg is a program, not a library we link, so a machine
// without it builds and runs everything else (docs/FARM.md "Video").
#pragma once

#include "engine/image/image.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace lsys {
class OutputFile;
class Process;
} // namespace lsys

namespace pf {

// The muxer ffmpeg writes for `path`'s extension (".mp4" → "mp4", ".mkv" →
// "matroska", ".mov" → "mov", any case); nullopt for any other.
std::optional<std::string> videoMuxerFor(const std::filesystem::path& path);

class VideoEncoder {
public:
    // Starts ffmpeg for frames of width × height at `fps` frames a second.
    // Throws std::runtime_error naming the file when the extension is not
    // one videoMuxerFor knows, PATH cannot be written (lsys::OutputFile) or
    // ffmpeg cannot be run. ffmpeg writes a temporary file beside PATH that
    // finish() renames over it: until then, and after any failure, an
    // existing PATH is left as it was.
    VideoEncoder(const std::filesystem::path& path, uint32_t width, uint32_t height, double fps);
    ~VideoEncoder(); // without finish(): ffmpeg stopped, its file removed
    VideoEncoder(const VideoEncoder&) = delete;
    VideoEncoder& operator=(const VideoEncoder&) = delete;

    // Throws std::runtime_error with ffmpeg's message when it stopped, or
    // when the frame is not width × height.
    void addFrame(const RgbaImage& frame);
    // Ends the stream and moves the file into place; throws with ffmpeg's
    // message when encoding failed.
    void finish();

private:
    std::filesystem::path path_;
    uint32_t width_, height_;
    std::unique_ptr<lsys::OutputFile> file_;
    std::unique_ptr<lsys::Process> ffmpeg_; // after file_: stopped before file_ removes what it wrote
};

} // namespace pf
