// OutputSet: a run's --out files appear all together or not at all. Write failures are real ones:
// RLIMIT_FSIZE makes write(2) fail with EFBIG the way a full disk fails it with ENOSPC, also for
// root (mode bits do not stop root's writes).
#include "lexel/cases/report/output.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <linux/fs.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/ioctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "lexel/cases/plot/curve_plot.h"
#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/image_io.h"

namespace lexel::cases {
namespace {

namespace fs = std::filesystem;

// A fresh directory per test, removed afterwards.
class OutputSetTest : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string pattern = (fs::temp_directory_path() / "lexel_output_test_XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        base = pattern;
    }
    void TearDown() override { fs::remove_all(base); }

    // Every entry under base, recursively, relative to it and sorted.
    std::vector<std::string> Entries() const {
        std::vector<std::string> names;
        for (const auto& e : fs::recursive_directory_iterator(base))
            names.push_back(e.path().lexically_relative(base).string());
        std::sort(names.begin(), names.end());
        return names;
    }

    fs::path base;
};

// A plan that declares every file name and no input.
OutputPlan AnyName() {
    return {{}, [](const std::string&) { return true; }};
}

std::string ReadAll(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void WriteAll(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

// Files larger than `bytes` cannot be written while this lives; SIGXFSZ is ignored, so write(2)
// returns EFBIG instead of killing the test.
class FileSizeLimit {
  public:
    explicit FileSizeLimit(rlim_t bytes) {
        ::getrlimit(RLIMIT_FSIZE, &saved_);
        previous_ = ::signal(SIGXFSZ, SIG_IGN);
        rlimit limit = saved_;
        limit.rlim_cur = bytes;
        ::setrlimit(RLIMIT_FSIZE, &limit);
    }
    ~FileSizeLimit() {
        ::setrlimit(RLIMIT_FSIZE, &saved_);
        ::signal(SIGXFSZ, previous_);
    }

  private:
    rlimit saved_{};
    void (*previous_)(int) = nullptr;
};

TEST_F(OutputSetTest, NewDirectoryAppearsWholeAtCommit) {
    const fs::path outDir = base / "a" / "b" / "out";
    {
        OutputSet out(outDir.string() + "/", AnyName());  // a trailing '/' names the same directory
        out.WriteText("report.json", "{}\n");
        out.WriteText("report.csv", "x,y\n1,2\n");
        EXPECT_FALSE(fs::exists(outDir));  // nothing is visible before Commit
        out.Commit();
        // DIR is not left locked by the staging directory it was: a next set stages in it.
        OutputSet next(outDir, AnyName());
    }
    EXPECT_EQ(ReadAll(outDir / "report.json"), "{}\n");
    EXPECT_EQ(ReadAll(outDir / "report.csv"), "x,y\n1,2\n");
    // No staging directory is left, and DIR has the mode mkdir(2) would give it (not mkdtemp's).
    EXPECT_EQ(Entries(), (std::vector<std::string>{"a", "a/b", "a/b/out", "a/b/out/report.csv",
                                                   "a/b/out/report.json"}));
    const ::mode_t mask = ::umask(022);
    ::umask(mask);
    EXPECT_EQ(fs::status(outDir).permissions(), static_cast<fs::perms>(0777 & ~mask));
}

TEST_F(OutputSetTest, WithoutCommitNothingIsLeft) {
    {
        OutputSet out(base / "made" / "for" / "out", AnyName());
        out.WriteText("report.md", "# report\n");
        EXPECT_EQ(Entries().size(), 4u);  // made, made/for, the staging dir, its file
    }
    EXPECT_TRUE(Entries().empty());  // the directories made for --out are gone too
    fs::create_directory(base / "existing");
    {
        OutputSet out(base / "existing", AnyName());
        out.WriteText("report.md", "# report\n");
    }
    EXPECT_EQ(Entries(), std::vector<std::string>{"existing"});
}

TEST_F(OutputSetTest, ExistingDirectoryKeepsOtherFilesAndReplacesItsOwn) {
    fs::create_directory(base / "out");
    WriteAll(base / "out" / "other.txt", "other");
    WriteAll(base / "out" / "report.csv", "old");
    {
        OutputSet out(base / "out", AnyName());
        out.WriteText("report.csv", "new");
        out.WriteText("report.md", "# new");
        out.Commit();
    }
    EXPECT_EQ(ReadAll(base / "out" / "other.txt"), "other");
    EXPECT_EQ(ReadAll(base / "out" / "report.csv"), "new");
    EXPECT_EQ(Entries(), (std::vector<std::string>{"out", "out/other.txt", "out/report.csv",
                                                   "out/report.md"}));
}

TEST_F(OutputSetTest, OutThatCannotHoldFilesIsBadInput) {
    WriteAll(base / "file", "x");
    try {
        OutputSet out(base / "file", AnyName());
        FAIL() << "a regular file accepted as --out";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "--out: " + (base / "file").string() + ": not a directory");
    }
    try {
        OutputSet out(base / "file" / "sub" / "out", AnyName());
        FAIL() << "a path through a regular file accepted as --out";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "--out: " + (base / "file/sub/out").string() +
                                             ": cannot create the directory (Not a directory)");
    }
    EXPECT_EQ(Entries(), std::vector<std::string>{"file"});
    EXPECT_EQ(ReadAll(base / "file"), "x");
}

// The full-disk finding: a text file larger than the space left. Before, the unchecked close
// published a truncated (often 0-byte) file under its final name.
TEST_F(OutputSetTest, FailedTextWritePublishesNothing) {
    fs::create_directory(base / "old");
    WriteAll(base / "old" / "report.md", "old");
    const std::string big(64 * 1024, 'x');
    for (const fs::path& outDir : {base / "new", base / "old"}) {
        try {
            OutputSet out(outDir, AnyName());
            const FileSizeLimit limit(4096);
            out.WriteText("report.csv", "small");
            out.WriteText("report.md", big);
            out.Commit();
            FAIL() << "a write past the file size limit succeeded";
        } catch (const std::runtime_error& e) {
            EXPECT_EQ(std::string(e.what()),
                      (outDir / "report.md").string() + ": write failed (File too large)");
        }
    }
    EXPECT_EQ(Entries(), (std::vector<std::string>{"old", "old/report.md"}));
    EXPECT_EQ(ReadAll(base / "old" / "report.md"), "old");
}

// The image findings: an image cut short by the disk (cairo's PNG, OpenImageIO's PNG) never
// reaches its final name, whether the writer notices or only the check at Commit does.
TEST_F(OutputSetTest, FailedImageWritePublishesNothing) {
    // Noise, so that the PNG stays larger than the limit after compression.
    spatial::Image image = spatial::MakeImage(256, 256, 3);
    std::uint32_t state = 12345;
    for (float& v : image.pixels) v = ((state = state * 1664525u + 1013904223u) >> 24) / 255.0f;
    std::vector<LowresCurve> curves(1);
    curves[0].label = "curve";
    curves[0].pixels = {5, 10, 20, 40};
    curves[0].extraPercent = {4, 3, 2, 1};
    for (const std::string name : {"image.png", "plot.png"}) {
        try {
            OutputSet out(base / "out", AnyName());
            const FileSizeLimit limit(2000);
            out.Writing([&] {
                if (name == "image.png")
                    spatial::WriteImage(out.Staged(name).string(), image);
                else
                    WriteLowresPlot(out.Staged(name).string(), "plot", curves);
            });
            out.Commit();
            FAIL() << name << ": an image past the file size limit was published";
        } catch (const std::runtime_error& e) {
            // The error names the final path, not the staging directory's.
            EXPECT_EQ(std::string(e.what()).rfind((base / "out" / name).string() + ": ", 0), 0u)
                << e.what();
        }
        EXPECT_TRUE(Entries().empty()) << name;
    }
}

TEST_F(OutputSetTest, IncompletePngIsRefusedAtCommit) {
    const spatial::Image image = spatial::MakeImage(64, 64, 3, 0.25f);
    for (const char* damage : {"none", "empty", "truncated", "garbage"}) {
        SCOPED_TRACE(damage);
        const fs::path outDir = base / damage;
        try {
            OutputSet out(outDir, AnyName());
            const fs::path png = out.Staged("image.png");
            spatial::WriteImage(png.string(), image);
            const std::uintmax_t size = fs::file_size(png);
            if (damage == std::string("empty")) fs::resize_file(png, 0);
            if (damage == std::string("truncated")) fs::resize_file(png, size - 1);
            if (damage == std::string("garbage")) WriteAll(png, std::string(size, 'x'));
            out.Commit();
            EXPECT_EQ(damage, std::string("none"));
            EXPECT_EQ(fs::file_size(outDir / "image.png"), size);
        } catch (const std::runtime_error& e) {
            EXPECT_NE(damage, std::string("none"));
            EXPECT_EQ(std::string(e.what()).rfind(
                          (outDir / "image.png").string() + ": not a complete PNG image (", 0),
                      0u)
                << e.what();
            EXPECT_FALSE(fs::exists(outDir));
        }
    }
}

// Two runs into one --out: each stages under its own name (before, both wrote
// <file>.partial and 5 of 20 concurrent runs failed).
TEST_F(OutputSetTest, ConcurrentSetsDoNotCollide) {
    fs::create_directory(base / "existing");
    for (const fs::path& outDir : {base / "existing", base / "absent"}) {
        constexpr int kRuns = 8;
        std::vector<std::string> errors(kRuns);
        std::vector<std::thread> runs;
        for (int r = 0; r < kRuns; ++r)
            runs.emplace_back([&, r] {
                try {
                    OutputSet out(outDir, AnyName());
                    out.WriteText("report.csv", "run " + std::to_string(r) + "\n");
                    out.WriteText("report.md", "run " + std::to_string(r) + "\n");
                    out.Commit();
                } catch (const std::exception& e) {
                    errors[r] = e.what();
                }
            });
        for (std::thread& t : runs) t.join();
        for (int r = 0; r < kRuns; ++r) EXPECT_EQ(errors[r], "") << outDir << " run " << r;
        // Each file is some run's whole file; no staging directory is left.
        EXPECT_EQ(ReadAll(outDir / "report.csv").substr(0, 4), "run ");
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(outDir))
            names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        EXPECT_EQ(names, (std::vector<std::string>{"report.csv", "report.md"}));
    }
    EXPECT_EQ(Entries().size(), 6u);
}

// An output named like a directory in DIR: refused before anything is computed (bad input), and,
// when the directory appears only after that, at Commit before any file of the set is moved.
TEST_F(OutputSetTest, OutputNamedLikeADirectoryReplacesNothing) {
    fs::create_directories(base / "out" / "b.csv");
    WriteAll(base / "out" / "a.csv", "old a");
    try {
        OutputSet out(base / "out", AnyName());
        FAIL() << "an output named like a directory was accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "--out: " + (base / "out" / "b.csv").string() +
                                             ": is a directory, and an output file has its name");
    }
    fs::remove(base / "out" / "b.csv");
    try {
        OutputSet out(base / "out", AnyName());
        out.WriteText("a.csv", "new a");
        out.WriteText("b.csv", "new b");
        fs::create_directories(base / "out" / "b.csv");
        out.Commit();
        FAIL() << "a directory was replaced by a file";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()),
                  (base / "out" / "b.csv").string() + ": is a directory; nothing was replaced");
    }
    EXPECT_EQ(ReadAll(base / "out" / "a.csv"), "old a");
    EXPECT_EQ(Entries(), (std::vector<std::string>{"out", "out/a.csv", "out/b.csv"}));
}

// Every --out that cannot be a directory is refused before anything is computed, with
// its reason (before, a symlink loop, a dangling link and a 300-byte name were found only by the
// final rename, exit 1 after computing, and an empty --out was ignored).
TEST_F(OutputSetTest, OutPathsThatCannotBeDirectoriesAreBadInput) {
    fs::create_symlink("loop", base / "loop");
    fs::create_symlink(base / "missing" / "target", base / "dangling");
    const std::string longName(300, 'n');
    std::string deep = base.string();
    while (deep.size() < 4000) deep += "/" + std::string(200, 'd');
    const std::vector<std::pair<fs::path, std::string>> refused = {
        {"", "--out: must name a directory, got an empty string"},
        {base / "loop", "--out: " + (base / "loop").string() + ": a symbolic link loop"},
        {base / "loop" / "sub",
         "--out: " + (base / "loop/sub").string() + ": a symbolic link loop on the way"},
        {base / "dangling", "--out: " + (base / "dangling").string() +
                                ": a dangling symbolic link (to " +
                                (base / "missing" / "target").string() + ", which does not exist)"},
        {base / longName, "--out: " + (base / longName).string() +
                              ": a path component is 300 bytes; a file name has at most 255"},
        {deep, "--out: " + deep + ": the path is " + std::to_string(deep.size()) +
                   " bytes; with its files' names it would pass the 4095 bytes a path may have"},
    };
    for (const auto& [outDir, message] : refused) {
        try {
            OutputSet out(outDir, AnyName());
            ADD_FAILURE() << outDir << " accepted";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()), message);
        }
    }
    EXPECT_EQ(Entries(), (std::vector<std::string>{"dangling", "loop"}));
}

// The plan names the files a command writes: a file outside it is a programming error, refused
// when it is staged by name and, when a writer put it in the staging directory itself, at Commit
// with nothing published.
TEST_F(OutputSetTest, UndeclaredOutputIsRefused) {
    const OutputPlan csvOnly{{}, [](const std::string& file) { return file.ends_with(".csv"); }};
    {
        OutputSet out(base / "out", csvOnly);
        out.WriteText("a.csv", "a");
        EXPECT_THROW(out.WriteText("a.json", "{}"), std::logic_error);
        WriteAll(out.StagingDir() / "b.png", "not declared");
        EXPECT_THROW(out.Commit(), std::logic_error);
    }
    EXPECT_TRUE(Entries().empty());
}

// The overwrite guard is the OutputSet's, so every command that reads a case has it (before, each
// command called it and `storage --case DIR/storage_x.json --out DIR` did not: it replaced its
// case file with its output). Through a directory link too.
TEST_F(OutputSetTest, OutputReplacingAnInputIsRefused) {
    fs::create_directory(base / "cases");
    WriteAll(base / "cases" / "storage_x.json", "{\"name\": \"x\"}");
    fs::create_directory_symlink(base / "cases", base / "link");
    const OutputPlan plan{{base / "cases" / "storage_x.json"}, [](const std::string& file) {
                              return file == "storage_x.json" || file == "storage_x.csv";
                          }};
    for (const fs::path& outDir : {base / "cases", base / "link"}) {
        try {
            OutputSet out(outDir, plan);
            ADD_FAILURE() << outDir << ": an output replacing the case was accepted";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()), "--out: writing " +
                                                 (outDir / "storage_x.json").string() +
                                                 " would overwrite the case file " +
                                                 (base / "cases" / "storage_x.json").string());
        }
    }
    EXPECT_EQ(ReadAll(base / "cases" / "storage_x.json"), "{\"name\": \"x\"}");
    EXPECT_EQ(Entries(), (std::vector<std::string>{"cases", "cases/storage_x.json", "link"}));
}

// A later run removes what killed runs left — its own prefix, this user's directories,
// none that a live run holds — and nothing else.
TEST_F(OutputSetTest, DebrisOfKilledRunsIsRemovedButNoLiveStaging) {
    const fs::path outDir = base / "out";
    fs::create_directories(outDir / ".lexel-staging-dead1" / ".replaced");
    WriteAll(outDir / ".lexel-staging-dead1" / "report.csv", "debris");
    fs::create_directories(outDir / ".lexel-staging-dead2");
    fs::create_directories(base / "elsewhere");
    WriteAll(base / "elsewhere" / "keep.txt", "keep");
    fs::create_directory_symlink(base / "elsewhere", outDir / ".lexel-staging-link");
    fs::create_directories(outDir / ".lexel-staging-theirs");
    const bool root = ::geteuid() == 0;
    if (root) {
        ASSERT_EQ(::chown((outDir / ".lexel-staging-theirs").c_str(), 65534, 65534), 0);
    }
    fs::create_directories(outDir / ".lexel-other");
    fs::create_directories(base / ".lexel-staging-beside");  // beside a new DIR
    const OutputPlan csv{{}, [](const std::string& file) { return file == "report.csv"; }};
    OutputSet live(outDir, csv);
    const std::string liveName = live.StagingDir().filename().string();
    {
        OutputSet later(outDir, csv);
        OutputSet beside(base / "new", csv);
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(outDir))
            names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        std::vector<std::string> expected = {".lexel-other", ".lexel-staging-link",
                                             later.StagingDir().filename().string(), liveName};
        if (root) expected.push_back(".lexel-staging-theirs");
        std::sort(expected.begin(), expected.end());
        EXPECT_EQ(names, expected);
        EXPECT_FALSE(fs::exists(base / ".lexel-staging-beside"));
        EXPECT_TRUE(fs::exists(beside.StagingDir()));
    }
    EXPECT_EQ(ReadAll(base / "elsewhere" / "keep.txt"), "keep");
    EXPECT_TRUE(fs::exists(live.StagingDir()));
    // An --out named through a directory link is cleaned the same.
    fs::create_directories(outDir / ".lexel-staging-dead3");
    fs::create_directory_symlink(outDir, base / "outlink");
    {
        OutputSet throughLink(base / "outlink", csv);
        EXPECT_FALSE(fs::exists(outDir / ".lexel-staging-dead3"));
    }
}

// The inode attributes of chattr(1), set through FS_IOC_SETFLAGS; false where the file system or
// the user cannot (then the tests that need them skip).
bool SetAttribute(const fs::path& path, int flag, bool on) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) return false;
    int flags = 0;
    bool done = ::ioctl(fd, FS_IOC_GETFLAGS, &flags) == 0;
    flags = on ? (flags | flag) : (flags & ~flag);
    done = done && ::ioctl(fd, FS_IOC_SETFLAGS, &flags) == 0;
    ::close(fd);
    return done;
}

// Clears an attribute again when the test ends (the fixture could not remove the file).
class AttributeGuard {
  public:
    AttributeGuard(fs::path path, int flag) : path_(std::move(path)), flag_(flag) {
        set_ = SetAttribute(path_, flag_, true);
    }
    ~AttributeGuard() {
        if (set_) SetAttribute(path_, flag_, false);
    }
    bool Set() const { return set_; }

  private:
    fs::path path_;
    int flag_;
    bool set_ = false;
};

// An append-only --out (chattr +a) takes new files, and the staging directory, made
// beside it, goes (before, one was left inside after every successful run); an old output there
// cannot be replaced, so it is refused before anything is computed.
TEST_F(OutputSetTest, AppendOnlyDirectoryKeepsNoStaging) {
    const fs::path outDir = base / "out";
    fs::create_directory(outDir);
    WriteAll(outDir / "other.txt", "other");
    const AttributeGuard appendOnly(outDir, FS_APPEND_FL);
    if (!appendOnly.Set()) GTEST_SKIP() << "chattr +a is not available here";
    const OutputPlan report{{}, [](const std::string& file) { return file == "report.csv"; }};
    {
        OutputSet out(outDir, report);
        EXPECT_EQ(out.StagingDir().parent_path(), base);
        out.WriteText("report.csv", "new");
        out.Commit();
    }
    EXPECT_EQ(Entries(), (std::vector<std::string>{"out", "out/other.txt", "out/report.csv"}));
    try {
        OutputSet out(outDir, report);
        FAIL() << "an old file in an append-only --out was to be replaced";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "--out: " + outDir.string() +
                                             ": is append-only (chattr +a), so its old "
                                             "report.csv cannot be replaced");
    }
    const OutputPlan csvOnly{{}, [](const std::string& file) { return file == "new.csv"; }};
    {
        OutputSet out(outDir, csvOnly);  // report.csv is not among its outputs
        out.WriteText("new.csv", "new");
        out.Commit();
    }
    EXPECT_EQ(Entries(),
              (std::vector<std::string>{"out", "out/new.csv", "out/other.txt", "out/report.csv"}));
}

// Runs `body` in a child process as the user nobody (65534) with root as its saved user, so that
// it can switch back with seteuid(0). Returns what the body returned (its exit status), 125 if
// it could not switch. Another user's files in a directory of nobody's: Linux's
// fs.protected_hardlinks forbids nobody to hard-link them (root's CAP_FOWNER would pass), but
// nobody may rename over them.
template <class Body>
int AsNobody(Body body) {
    const pid_t child = ::fork();
    if (child == 0) {
        if (::setresgid(65534, 65534, 0) != 0 || ::setresuid(65534, 65534, 0) != 0) ::_exit(125);
        ::_exit(body());
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 126;
}

bool ProtectedHardlinks() {
    std::ifstream setting("/proc/sys/fs/protected_hardlinks");
    int value = 0;
    return (setting >> value) && value == 1;
}

// A data loss once: the old files of an existing --out could not be kept as hard links
// (another user's), and a later rename failed; the rollback then deleted each file it could not
// restore (78 of 79 gone) and said "no file was replaced". Here a.csv cannot be kept and b.csv
// cannot be replaced (immutable): now the run refuses before replacing anything — at once when
// the old files are there before it computes, at Commit when they appear after.
TEST_F(OutputSetTest, OldFilesThatCannotBeKeptAreNeverReplaced) {
    if (::geteuid() != 0 || !ProtectedHardlinks())
        GTEST_SKIP() << "needs root and fs.protected_hardlinks = 1";
    const fs::path outDir = base / "out";
    fs::create_directory(outDir);
    ASSERT_EQ(::chown(base.c_str(), 65534, 65534), 0);
    ASSERT_EQ(::chown(outDir.c_str(), 65534, 65534), 0);
    // Root's old files; b.csv made immutable while the test runs.
    const auto writeOldFiles = [&] {
        WriteAll(outDir / "a.csv", "old a");
        WriteAll(outDir / "b.csv", "old b");
        return SetAttribute(outDir / "b.csv", FS_IMMUTABLE_FL, true);
    };
    const std::string keepA = (outDir / "a.csv").string() +
                              ": cannot keep the old file to restore it if publishing fails "
                              "(link: Operation not permitted: another user's file "
                              "(fs.protected_hardlinks), or an immutable or append-only one)";
    // Before computing: a bad --out.
    if (!writeOldFiles()) GTEST_SKIP() << "chattr +i is not available here";
    const int before = AsNobody([&] {
        try {
            OutputSet out(outDir, AnyName());
        } catch (const InputError& e) {
            return std::string(e.what()) == "--out: " + keepA ? 0 : 2;
        }
        return 1;
    });
    EXPECT_EQ(before, 0) << "1: accepted, 2: another message";
    SetAttribute(outDir / "b.csv", FS_IMMUTABLE_FL, false);
    fs::remove(outDir / "a.csv");
    fs::remove(outDir / "b.csv");
    // At Commit: the old files appear while the run computes.
    const int atCommit = AsNobody([&] {
        try {
            OutputSet out(outDir, AnyName());
            out.WriteText("a.csv", "new a");
            out.WriteText("b.csv", "new b");
            if (::seteuid(0) != 0 || !writeOldFiles() || ::seteuid(65534) != 0) return 3;
            out.Commit();
        } catch (const std::runtime_error& e) {
            return std::string(e.what()) == keepA + "; nothing was replaced" ? 0 : 2;
        }
        return 1;
    });
    EXPECT_EQ(atCommit, 0) << "1: published, 2: another message, 3: setup failed";
    SetAttribute(outDir / "b.csv", FS_IMMUTABLE_FL, false);
    EXPECT_EQ(ReadAll(outDir / "a.csv"), "old a");  // before the fix: deleted
    EXPECT_EQ(ReadAll(outDir / "b.csv"), "old b");
    EXPECT_EQ(Entries(), (std::vector<std::string>{"out", "out/a.csv", "out/b.csv"}));
}

// A child process that stops cleanly on signals, as lexel does, and stages a set in `outDir`:
// `ready` runs first (files staged before the parent goes on), then `busy` (never returning:
// computing or writing). Returns the child's pid once `ready` is done.
pid_t ForkStagingRun(const fs::path& outDir, const std::function<void(OutputSet&)>& ready,
                     const std::function<void(OutputSet&)>& busy) {
    int pipeFds[2];
    if (::pipe(pipeFds) != 0) return -1;
    const pid_t child = ::fork();
    if (child == 0) {
        StopCleanlyOnSignals();
        OutputSet out(outDir, AnyName());
        ready(out);
        const char byte = 1;
        if (::write(pipeFds[1], &byte, 1) != 1) ::_exit(1);
        busy(out);
        ::_exit(1);
    }
    char byte = 0;
    const bool started = child > 0 && ::read(pipeFds[0], &byte, 1) == 1;
    ::close(pipeFds[0]);
    ::close(pipeFds[1]);
    return started ? child : -1;
}

// Sends `signal` and returns the child's exit status (-1 when it did not exit by itself).
int StopWith(pid_t child, int signal) {
    ::kill(child, signal);
    int status = 0;
    ::waitpid(child, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// SIGTERM (SIGINT, SIGHUP) removes the staging directory and exits with 128 + n
// (before, no handler: the staging directory stayed like after SIGKILL).
TEST_F(OutputSetTest, TerminationSignalRemovesTheStaging) {
    for (const int signal : {SIGTERM, SIGINT}) {
        const pid_t child = ForkStagingRun(
            base / "out", [](OutputSet& out) { out.WriteText("report.csv", "half done"); },
            [](OutputSet&) {
                for (;;) ::pause();  // computing
            });
        ASSERT_GT(child, 0);
        EXPECT_EQ(Entries().size(), 2u);  // the staging directory and its file
        EXPECT_EQ(StopWith(child, signal), 128 + signal);
        EXPECT_TRUE(Entries().empty());
    }
}

// A signal while the run writes its files (a 3D run's images take seconds): the signal thread
// removes the staging directory while the writing thread keeps creating files in it. Before, the
// removal listed the files, the writer made another, and rmdir failed: the staging directory stayed
// with the files made meanwhile (80 of 100 such runs here), as after SIGKILL.
TEST_F(OutputSetTest, SignalWhileWritingRemovesTheStaging) {
    constexpr int kRuns = 30;
    int left = 0;
    for (int run = 0; run < kRuns; ++run) {
        const pid_t child = ForkStagingRun(
            base / "out", [](OutputSet&) {},
            [](OutputSet& out) {
                try {
                    for (int i = 0;; ++i) out.WriteText("f" + std::to_string(i) + ".csv", "x");
                } catch (const std::runtime_error&) {
                    for (;;) ::pause();  // the staging directory is gone: wait for the exit
                }
            });
        ASSERT_GT(child, 0);
        ::usleep(5000 + 1000 * (run % 10));  // some files written
        EXPECT_EQ(StopWith(child, SIGTERM), 128 + SIGTERM);
        if (!Entries().empty()) {
            ++left;
            for (const auto& e : fs::directory_iterator(base)) fs::remove_all(e.path());
        }
    }
    EXPECT_EQ(left, 0) << "of " << kRuns << " runs stopped while writing left their staging";
}

// A signal while Commit renames the files into an existing DIR (cases/README.md: one "that comes
// during the renames waits for them to finish, so a signal never leaves a mix"): the run replaces
// kFiles old files and is stopped as soon as the first new one (in Commit's order: sorted) is in
// place. Without the lock Commit holds, the signal thread removed the staging directory mid-rename
// and the process ended with the first files new and the rest old.
TEST_F(OutputSetTest, SignalDuringTheRenamesLeavesNoMix) {
    constexpr int kFiles = 300;
    const fs::path outDir = base / "out";
    const auto name = [](int i) {
        std::string digits = std::to_string(i);
        return "f" + std::string(3 - digits.size(), '0') + digits + ".csv";
    };
    fs::create_directory(outDir);
    for (int i = 0; i < kFiles; ++i) WriteAll(outDir / name(i), "old");
    const pid_t child = ForkStagingRun(
        outDir,
        [&](OutputSet& out) {
            for (int i = 0; i < kFiles; ++i) out.WriteText(name(i), "new");
        },
        [](OutputSet& out) {
            out.Commit();
            for (;;) ::pause();  // published: wait for the exit
        });
    ASSERT_GT(child, 0);
    bool renaming = false;
    for (int poll = 0; poll < 20'000'000 && !renaming; ++poll)  // at most a few minutes
        renaming = ReadAll(outDir / name(0)) == "new";
    const bool done = ReadAll(outDir / name(kFiles - 1)) == "new";
    EXPECT_EQ(StopWith(child, SIGTERM), 128 + SIGTERM);
    ASSERT_TRUE(renaming) << "the run never published";
    int fresh = 0;
    for (int i = 0; i < kFiles; ++i) fresh += ReadAll(outDir / name(i)) == "new";
    EXPECT_EQ(fresh, kFiles) << "files new after the signal";
    EXPECT_EQ(Entries().size(), kFiles + 1u) << "the staging directory was left";
    std::cout << "[   INFO   ] the signal came " << (done ? "after" : "during") << " the renames\n";
}

}  // namespace
}  // namespace lexel::cases
