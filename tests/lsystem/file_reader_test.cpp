// lsys::readFileUpTo (lsystem/common/file_reader.h), through which every
// loader reads its input: only regular files are read. A fifo without a
// writer would block the open for ever and a device may never end, so both
// are refused at once, as is a socket; the plant reader says so to `lsys`.
#include "lsystem/common/file_reader.h"
#include "lsystem/language/parser.h"
#include "test_folder.h"

#include <gtest/gtest.h>

#include <fstream>

#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

namespace lsys {
namespace {

namespace fs = std::filesystem;

constexpr size_t kLimit = size_t(1) << 20;

TEST(FileReader, ReadsARegularFile) {
    const fs::path file = pf::test::testFolder("file_reader") / "plant.lsys";
    std::ofstream(file) << "Axiom: F\n";
    const FileBytes read = readFileUpTo(file, kLimit);
    EXPECT_EQ(read.problem, FileProblem::None);
    EXPECT_EQ(read.bytes, "Axiom: F\n");
}

TEST(FileReader, RefusesAFifoWithoutWaitingForAWriter) {
    const fs::path fifo = pf::test::testFolder("file_reader") / "plant.lsys";
    fs::remove(fifo);
    ASSERT_EQ(mkfifo(fifo.c_str(), 0644), 0);
    const FileBytes read = readFileUpTo(fifo, kLimit);
    EXPECT_EQ(read.problem, FileProblem::NotRegular);
    std::string problem;
    readTextFile(fifo.string(), problem);
    EXPECT_EQ(problem, "is not a regular file (a fifo, a device or a socket)");
    fs::remove(fifo);
}

TEST(FileReader, RefusesADeviceWithoutReadingIt) {
    EXPECT_EQ(readFileUpTo("/dev/zero", kLimit).problem, FileProblem::NotRegular);
    EXPECT_EQ(readFileUpTo("/dev/null", kLimit).problem, FileProblem::NotRegular);
}

TEST(FileReader, RefusesASocket) {
    const fs::path path = pf::test::testFolder("file_reader") / "s";
    fs::remove(path);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    ASSERT_LT(path.string().size(), sizeof address.sun_path);
    path.string().copy(address.sun_path, sizeof address.sun_path - 1);
    const int listening = socket(AF_UNIX, SOCK_STREAM, 0);
    ASSERT_GE(listening, 0);
    ASSERT_EQ(bind(listening, reinterpret_cast<const sockaddr*>(&address), sizeof address), 0);
    EXPECT_EQ(readFileUpTo(path, kLimit).problem, FileProblem::NotRegular);
    close(listening);
    fs::remove(path);
}

TEST(FileReader, NamesAFolderAndAMissingFile) {
    const fs::path folder = pf::test::testFolder("file_reader");
    EXPECT_EQ(readFileUpTo(folder, kLimit).problem, FileProblem::Folder);
    EXPECT_EQ(readFileUpTo(folder / "missing.lsys", kLimit).problem, FileProblem::CannotOpen);
}

TEST(FileReader, RefusesAFileLargerThanTheLimitFromItsSize) {
    const fs::path file = pf::test::testFolder("file_reader") / "large.lsys";
    std::ofstream(file) << std::string(100, 'F');
    EXPECT_EQ(readFileUpTo(file, 99).problem, FileProblem::TooLarge);
    EXPECT_EQ(readFileUpTo(file, 100).problem, FileProblem::None);
}

} // namespace
} // namespace lsys
