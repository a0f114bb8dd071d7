// OutputSet: a run's --out files appear all together or not at all (issue 16, "atomic output,
// really"). Write failures are real ones: RLIMIT_FSIZE makes write(2) fail with EFBIG the way a
// full disk fails it with ENOSPC, also for root (mode bits do not stop root's writes).
#include "lexel/cases/report/output.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "lexel/cases/report/figures.h"
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
            names.push_back(fs::relative(e.path(), base).string());
        std::sort(names.begin(), names.end());
        return names;
    }

    fs::path base;
};

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
        OutputSet out(outDir.string() + "/");  // a trailing '/' names the same directory
        out.WriteText("report.json", "{}\n");
        out.WriteText("report.csv", "x,y\n1,2\n");
        EXPECT_FALSE(fs::exists(outDir));  // nothing is visible before Commit
        out.Commit();
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
        OutputSet out(base / "made" / "for" / "out");
        out.WriteText("report.md", "# report\n");
        EXPECT_EQ(Entries().size(), 4u);  // made, made/for, the staging dir, its file
    }
    EXPECT_TRUE(Entries().empty());  // the directories made for --out are gone too
    fs::create_directory(base / "existing");
    {
        OutputSet out(base / "existing");
        out.WriteText("report.md", "# report\n");
    }
    EXPECT_EQ(Entries(), std::vector<std::string>{"existing"});
}

TEST_F(OutputSetTest, ExistingDirectoryKeepsOtherFilesAndReplacesItsOwn) {
    fs::create_directory(base / "out");
    WriteAll(base / "out" / "other.txt", "other");
    WriteAll(base / "out" / "report.csv", "old");
    {
        OutputSet out(base / "out");
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
        OutputSet out(base / "file");
        FAIL() << "a regular file accepted as --out";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "--out: " + (base / "file").string() + ": not a directory");
    }
    try {
        OutputSet out(base / "file" / "sub" / "out");
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
            OutputSet out(outDir);
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
            OutputSet out(base / "out");
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
            OutputSet out(outDir);
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
                    OutputSet out(outDir);
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

// A file that cannot be replaced (a directory of that name) stops the commit before any file of
// the set is moved.
TEST_F(OutputSetTest, CommitReplacesNoFileWhenOneCannotBeReplaced) {
    fs::create_directories(base / "out" / "b.csv");
    WriteAll(base / "out" / "a.csv", "old a");
    try {
        OutputSet out(base / "out");
        out.WriteText("a.csv", "new a");
        out.WriteText("b.csv", "new b");
        out.Commit();
        FAIL() << "a directory was replaced by a file";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()),
                  (base / "out" / "b.csv").string() + ": is a directory; nothing was replaced");
    }
    EXPECT_EQ(ReadAll(base / "out" / "a.csv"), "old a");
    EXPECT_EQ(Entries(), (std::vector<std::string>{"out", "out/a.csv", "out/b.csv"}));
}

}  // namespace
}  // namespace lexel::cases
