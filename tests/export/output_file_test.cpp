// lsys::OutputFile and outputPathProblem: files written whole, only over
// regular files, links followed, never a device, fifo, folder or read-only
// file replaced, and never a file the run reads.
#include "gltf_reading.h"

#include "lsystem/common/file_reader.h"
#include "lsystem/common/output_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sys/stat.h>
#include <sys/types.h>

namespace {
namespace fs = std::filesystem;

class OutputFileTest : public plantfield::test::ExportDirTest {
protected:
    std::string contentOf(const fs::path& path) const {
        std::ifstream in(path, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    }
    void write(const fs::path& path, const std::string& text) const {
        lsys::OutputFile file(path);
        file.stream() << text;
        file.commit();
    }
    // The message of writing to `path`, which must fail.
    // A refusal is OutputRefusedError, which the tools report as bad input (exit 2).
    std::string failureOf(const fs::path& path) const {
        try {
            write(path, "new");
        } catch (const lsys::OutputRefusedError& error) {
            return error.what();
        }
        ADD_FAILURE() << "writing " << path << " did not fail";
        return {};
    }
    size_t entries() const { return size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator())); }
};

TEST_F(OutputFileTest, WritesANewFileAndReplacesARegularOne) {
    write(dir / "a.txt", "first");
    EXPECT_EQ(contentOf(dir / "a.txt"), "first");
    write(dir / "a.txt", "second");
    EXPECT_EQ(contentOf(dir / "a.txt"), "second");
    EXPECT_EQ(entries(), 1u); // no temporary file left
}

TEST_F(OutputFileTest, KeepsTheModeOfTheFileItReplaces) {
    write(dir / "script.sh", "one");
    fs::permissions(dir / "script.sh", fs::perms::owner_all);
    write(dir / "script.sh", "two");
    EXPECT_EQ(fs::status(dir / "script.sh").permissions(), fs::perms::owner_all);
}

TEST_F(OutputFileTest, UncommittedLeavesNothingAndTheOldFileIntact) {
    write(dir / "keep.txt", "old");
    {
        lsys::OutputFile file(dir / "keep.txt");
        file.stream() << "half";
    }
    EXPECT_EQ(contentOf(dir / "keep.txt"), "old");
    EXPECT_EQ(entries(), 1u);
}

TEST_F(OutputFileTest, RefusesAReadOnlyFileEvenForRoot) {
    write(dir / "locked.txt", "old");
    fs::permissions(dir / "locked.txt", fs::perms::owner_read | fs::perms::group_read);
    EXPECT_NE(failureOf(dir / "locked.txt").find("is read-only"), std::string::npos);
    EXPECT_EQ(contentOf(dir / "locked.txt"), "old");
    EXPECT_EQ(entries(), 1u);
}

TEST_F(OutputFileTest, RefusesAFifoAndLeavesItAFifo) {
    ASSERT_EQ(mkfifo((dir / "pipe").c_str(), 0644), 0);
    EXPECT_NE(failureOf(dir / "pipe").find("is a fifo"), std::string::npos);
    EXPECT_TRUE(fs::is_fifo(dir / "pipe"));
    EXPECT_EQ(entries(), 1u);
}

TEST_F(OutputFileTest, RefusesAFolder) {
    fs::create_directory(dir / "taken.png");
    EXPECT_NE(failureOf(dir / "taken.png").find("is a folder"), std::string::npos);
    EXPECT_TRUE(fs::is_directory(dir / "taken.png"));
}

TEST_F(OutputFileTest, DevicesAreNotWritableTargets) {
    // Only asked, never written: a broken check would replace the device.
    EXPECT_NE(lsys::outputPathProblem("/dev/null").find("is a device"), std::string::npos);
    EXPECT_NE(lsys::outputPathProblem("/dev/full").find("is a device"), std::string::npos);
}

TEST_F(OutputFileTest, FollowsASymbolicLinkAndKeepsIt) {
    fs::create_directory(dir / "real");
    write(dir / "real" / "image.png", "old");
    fs::create_symlink(dir / "real" / "image.png", dir / "link.png");
    write(dir / "link.png", "new");
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir / "link.png")));
    EXPECT_EQ(contentOf(dir / "real" / "image.png"), "new");
}

TEST_F(OutputFileTest, RefusesALinkToNothingAndAMissingFolder) {
    fs::create_symlink(dir / "nowhere" / "x.png", dir / "dangling.png");
    EXPECT_NE(failureOf(dir / "dangling.png").find("symbolic link to nothing"), std::string::npos);
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir / "dangling.png")));
    EXPECT_NE(failureOf(dir / "missing" / "x.png").find("does not exist"), std::string::npos);
    EXPECT_NE(lsys::outputPathProblem("").find("empty"), std::string::npos);
}

TEST_F(OutputFileTest, RefusesAnInputByAnyName) {
    write(dir / "scene.json", "{}");
    fs::create_directory(dir / "sub");
    fs::create_symlink(dir / "scene.json", dir / "link.json");
    fs::create_hard_link(dir / "scene.json", dir / "hard.json");
    const std::vector<fs::path> inputs{dir / "sub" / ".." / "scene.json"};
    for (const fs::path& output : {dir / "scene.json", dir / "link.json", dir / "hard.json"})
        EXPECT_NE(lsys::outputPathProblem(output, inputs).find("is the input"), std::string::npos) << output;
    EXPECT_EQ(lsys::outputPathProblem(dir / "other.json", inputs), "");
}

TEST_F(OutputFileTest, RefusesAFileTheThreadsReadLogRecorded) {
    write(dir / "plant.lsys", "axiom: F");
    fs::create_directory(dir / "sub");
    EXPECT_EQ(lsys::outputPathProblem(dir / "plant.lsys"), ""); // no log open: nothing read yet
    const lsys::ReadFileLog run;
    {
        const lsys::ReadFileLog load; // a load nested in the run, closed before the output opens
        lsys::readFileUpTo(dir / "plant.lsys", 1 << 10);
    }
    for (const fs::path& output : {dir / "plant.lsys", dir / "sub" / ".." / "plant.lsys"})
        EXPECT_NE(failureOf(output).find("never replaces a file the run reads"), std::string::npos) << output;
    EXPECT_EQ(contentOf(dir / "plant.lsys"), "axiom: F");
    write(dir / "image.png", "written"); // outputs that are not inputs are written
    EXPECT_EQ(contentOf(dir / "image.png"), "written");
}

} // namespace
