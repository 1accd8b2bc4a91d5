// Output files: modes, symlinks, targets written in place, and several files all or none.

#include "catplan/base/output_file.hpp"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

namespace catplan {
namespace {

namespace fs = std::filesystem;

// A fresh directory per test, removed afterwards.
class OutputSetTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("catplan_output_set_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }

    void TearDown() override { fs::remove_all(dir_); }

    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    static std::string read(const std::string& p) {
        std::ifstream in(p, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        return text.str();
    }

    static mode_t mode_of(const std::string& p) {
        struct stat st {};

        EXPECT_EQ(::stat(p.c_str(), &st), 0) << p;
        return st.st_mode & 07777;
    }

    std::size_t entries() const {
        return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), {}));
    }

    fs::path dir_;
};

// The umask for the duration of a test.
struct Umask {
    mode_t old;

    explicit Umask(mode_t m) : old(::umask(m)) {}

    ~Umask() { ::umask(old); }
};

TEST_F(OutputSetTest, NewFileGetsTheUsualModeOf0666LessTheUmask) {
    std::string error;
    {
        Umask u(022);
        ASSERT_TRUE(write_file_atomically(path("a.txt"), "a\n", error)) << error;
    }
    EXPECT_EQ(mode_of(path("a.txt")), 0644u);
    {
        Umask u(027);
        ASSERT_TRUE(write_file_atomically(path("b.txt"), "b\n", error)) << error;
    }
    EXPECT_EQ(mode_of(path("b.txt")), 0640u);
    EXPECT_EQ(read(path("b.txt")), "b\n");
}

TEST_F(OutputSetTest, ReplacedFileKeepsItsMode) {
    std::string error;
    for (mode_t mode : {0644u, 0600u, 0755u}) {
        ASSERT_TRUE(write_file_atomically(path("x"), "old\n", error)) << error;
        ASSERT_EQ(::chmod(path("x").c_str(), mode), 0);
        Umask u(077); // the umask applies to new files only
        ASSERT_TRUE(write_file_atomically(path("x"), "new\n", error)) << error;
        EXPECT_EQ(mode_of(path("x")), mode);
        EXPECT_EQ(read(path("x")), "new\n");
    }
    EXPECT_EQ(entries(), 1u); // no temporary file left behind
}

TEST_F(OutputSetTest, SymlinkIsFollowedAndStaysALink) {
    std::string error;
    ASSERT_TRUE(write_file_atomically(path("real.txt"), "old\n", error)) << error;
    ASSERT_EQ(::chmod(path("real.txt").c_str(), 0640), 0);
    fs::create_directories(dir_ / "sub");
    fs::create_symlink("../real.txt", dir_ / "sub" / "link.txt"); // relative to the link's dir
    fs::create_symlink("sub/link.txt", dir_ / "link2.txt");       // a chain of two
    ASSERT_TRUE(write_file_atomically(path("link2.txt"), "new\n", error)) << error;
    EXPECT_TRUE(fs::is_symlink(dir_ / "link2.txt"));
    EXPECT_TRUE(fs::is_symlink(dir_ / "sub" / "link.txt"));
    EXPECT_EQ(read(path("real.txt")), "new\n");
    EXPECT_EQ(mode_of(path("real.txt")), 0640u);
    // A dangling link creates the file it points to, as the shell's `>` does.
    fs::create_symlink("made.txt", dir_ / "dangling");
    ASSERT_TRUE(write_file_atomically(path("dangling"), "made\n", error)) << error;
    EXPECT_TRUE(fs::is_symlink(dir_ / "dangling"));
    EXPECT_EQ(read(path("made.txt")), "made\n");
    // A loop of links is an error, not a hang.
    fs::create_symlink("loop2", dir_ / "loop1");
    fs::create_symlink("loop1", dir_ / "loop2");
    EXPECT_FALSE(write_file_atomically(path("loop1"), "x", error));
    EXPECT_NE(error.find("loop1"), std::string::npos) << error;
}

TEST_F(OutputSetTest, FifoIsWrittenInPlace) {
    ASSERT_EQ(::mkfifo(path("fifo").c_str(), 0600), 0);
    std::string received;
    std::thread reader([&] { received = read(path("fifo")); });
    std::string error;
    EXPECT_TRUE(write_file_atomically(path("fifo"), "through the pipe\n", error)) << error;
    reader.join();
    EXPECT_EQ(received, "through the pipe\n");

    struct stat st {};

    ASSERT_EQ(::lstat(path("fifo").c_str(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode));
    EXPECT_EQ(entries(), 1u);
}

TEST_F(OutputSetTest, DeviceIsWrittenInPlaceNotReplaced) {
    std::string error;
    EXPECT_TRUE(write_file_atomically("/dev/null", "discarded\n", error)) << error;

    struct stat st {};

    ASSERT_EQ(::lstat("/dev/null", &st), 0);
    EXPECT_TRUE(S_ISCHR(st.st_mode));
    // A device that fails the write reports it.
    if (::access("/dev/full", W_OK) == 0) {
        EXPECT_FALSE(write_file_atomically("/dev/full", "x", error));
        EXPECT_NE(error.find("/dev/full"), std::string::npos) << error;
    }
}

TEST_F(OutputSetTest, ProcessDescriptorLinkIsWrittenInPlace) {
    // /dev/stdout is /proc/self/fd/1: a pipe there is written, a redirected file appended to.
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    std::string error;
    EXPECT_TRUE(write_file_atomically("/dev/fd/" + std::to_string(fds[1]), "piped\n", error))
        << error;
    ::close(fds[1]);
    char buffer[32] = {};
    EXPECT_EQ(::read(fds[0], buffer, sizeof buffer), 6);
    EXPECT_EQ(std::string(buffer), "piped\n");
    ::close(fds[0]);

    ASSERT_TRUE(write_file_atomically(path("redirected"), "first\n", error)) << error;
    int fd = ::open(path("redirected").c_str(), O_WRONLY | O_APPEND);
    ASSERT_GE(fd, 0);

    struct stat before {};

    ASSERT_EQ(::stat(path("redirected").c_str(), &before), 0);
    EXPECT_TRUE(write_file_atomically("/proc/self/fd/" + std::to_string(fd), "second\n", error))
        << error;
    ::close(fd);

    struct stat after {};

    ASSERT_EQ(::stat(path("redirected").c_str(), &after), 0);
    EXPECT_EQ(before.st_ino, after.st_ino); // the same file, not a replacement
    EXPECT_EQ(read(path("redirected")), "first\nsecond\n");
}

TEST_F(OutputSetTest, DirectoryAndMissingDirectoryAreErrors) {
    std::string error;
    EXPECT_FALSE(write_file_atomically(dir_.string(), "x", error));
    EXPECT_NE(error.find("Is a directory"), std::string::npos) << error;
    EXPECT_FALSE(write_file_atomically(path("missing/x.txt"), "x", error));
    EXPECT_NE(error.find("missing/x.txt"), std::string::npos) << error;
    EXPECT_EQ(entries(), 0u);
}

TEST_F(OutputSetTest, SeveralFilesAreWrittenAllOrNone) {
    std::string error;
    ASSERT_TRUE(write_file_atomically(path("kept.txt"), "before\n", error)) << error;
    {
        OutputSet set;
        ASSERT_TRUE(set.stage(path("new.txt"), "new\n", error)) << error;
        ASSERT_TRUE(set.stage(path("kept.txt"), "after\n", error)) << error;
        EXPECT_FALSE(set.stage(path("missing/p.txt"), "p\n", error));
        // Not committed: the set goes away without touching a target.
    }
    EXPECT_FALSE(fs::exists(path("new.txt")));
    EXPECT_EQ(read(path("kept.txt")), "before\n");
    EXPECT_EQ(entries(), 1u);

    OutputSet set;
    ASSERT_TRUE(set.stage(path("new.txt"), "new\n", error)) << error;
    ASSERT_TRUE(set.stage(path("kept.txt"), "after\n", error)) << error;
    EXPECT_FALSE(fs::exists(path("new.txt"))); // staged, not yet in place
    ASSERT_TRUE(set.commit(error)) << error;
    EXPECT_EQ(read(path("new.txt")), "new\n");
    EXPECT_EQ(read(path("kept.txt")), "after\n");
    EXPECT_EQ(entries(), 2u);
    EXPECT_FALSE(set.commit(error));
}

TEST_F(OutputSetTest, OneFileNamedTwiceIsAnError) {
    std::string error;
    OutputSet set;
    ASSERT_TRUE(set.stage(path("same.txt"), "a", error)) << error;
    fs::create_symlink("same.txt", dir_ / "alias");
    EXPECT_FALSE(set.stage(path("alias"), "b", error));
    EXPECT_NE(error.find("two outputs"), std::string::npos) << error;
}

} // namespace
} // namespace catplan
