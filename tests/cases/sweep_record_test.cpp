// The sweep record and journal: every cell survives writing and reading bit for bit,
// a merge of shards' records is the whole sweep's record, and records that are not one sweep are
// refused naming the light or the field.
#include "lexel/cases/record/sweep_record.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <bit>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#include "lexel/cases/record/sweep_journal.h"
#include "lexel/cases/record/sweep_record_reader.h"
#include "lexel/cases/record/sweep_record_text.h"
#include "lexel/cases/run/sweep_share.h"
#include "lexel/solvers/errors.h"
#include "scratch_directory.h"

namespace lexel::cases {
namespace {

namespace fs = std::filesystem;

constexpr double kInf = std::numeric_limits<double>::infinity();

// Doubles that a careless writer loses: non-finite, negative zero, subnormal, 17 digits.
SweepCell AwkwardCell(std::int64_t k) {
    SweepCell c;
    c.misclassified = 1000 + k;
    c.h = k == 0 ? kInf : 0.1 + 0.2 * static_cast<double>(k);
    c.ms = 1.0 / 3.0;
    c.hGrazing = k == 1 ? -0.0 : std::numeric_limits<double>::denorm_min();
    c.winner = k == 2 ? "lispsm-tight" : "";
    c.footprintMean = std::numeric_limits<double>::quiet_NaN();
    c.footprintMax = -kInf;
    c.uncovered = 7 * k;
    c.cascades = 4;
    c.emptyPartitions = 1;
    c.storageFactor = std::numeric_limits<double>::max();
    c.pagesRequested = k == 2 ? 12 : -1;
    c.pagesResident = k == 2 ? 10 : -1;
    c.pagesDropped = k == 2 ? 2 : -1;
    c.lodBias = 0.125;
    c.misclassifiedMean = 1000.0 + static_cast<double>(k) + 1.0 / 7.0;  // a phase mean
    c.misclassifiedError = k == 1 ? 0.0 : 0.1 + 1e-17 * static_cast<double>(k);
    c.e = k == 0 ? std::numeric_limits<double>::quiet_NaN() : 1.0 / 7.0;
    c.shimmer = k == 2 ? std::numeric_limits<double>::quiet_NaN() : 0.1 + 1.0 / 3.0;
    c.storageFactorP99 = 2.0 / 3.0 + static_cast<double>(k);
    c.phases = 16 << k;
    return c;
}

// A whole sweep's record: `lights` lights of two methods, one study count.
SweepRecord WholeRecord(std::size_t lights) {
    SweepRecord r;
    r.identity = {.caseName = "demo",
                  .caseHash = "0123456789abcdef",
                  .methods = {"optimal", "sdsm"},
                  .backend = "cpu",
                  .cascades = 2,
                  .phases = 16,
                  .maxPhases = 64,
                  .shimmerPoses = 3,
                  .lights = lights,
                  .lightsHash = ""};
    std::vector<spatial::Light> all;
    r.studyCounts = {1};
    r.study.assign(1, {});
    for (std::size_t i = 0; i < lights; ++i) {
        SweepLightRecord light;
        light.index = i;
        light.light.type =
            i % 2 ? spatial::Light::Type::kDirectional : spatial::Light::Type::kPoint;
        light.light.position = {1.0 / 3.0 + static_cast<double>(i), 1e-300, -7.25};
        light.light.direction = {0.1, -0.7, std::nextafter(0.2, 1.0)};
        light.receiverPixels = 11165 + static_cast<std::int64_t>(i);
        light.cells = {AwkwardCell(static_cast<std::int64_t>(i % 3)),
                       AwkwardCell(static_cast<std::int64_t>((i + 1) % 3))};
        all.push_back(light.light);
        r.lights.push_back(light);
        r.study[0].push_back({40.0 + static_cast<double>(i) + 1.0 / 3.0});
    }
    r.identity.lightsHash = LightsHash(all);
    r.seconds = 1.5;
    return r;
}

bool SameBits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b) ||
           (std::isnan(a) && std::isnan(b));
}

TEST(SweepRecord, EveryCellReadsBackBitForBit) {
    const SweepRecord written = WholeRecord(3);
    const std::string text = SweepRecordText(written);
    const SweepRecord read = ParseSweepRecord(text, "record");
    ASSERT_EQ(read.lights.size(), 3u);
    EXPECT_EQ(read.identity, written.identity);
    for (std::size_t l = 0; l < 3; ++l)
        for (std::size_t m = 0; m < 2; ++m) {
            const SweepCell& a = written.lights[l].cells[m];
            const SweepCell& b = read.lights[l].cells[m];
            EXPECT_EQ(a.misclassified, b.misclassified);
            for (const auto field :
                 {&SweepCell::h, &SweepCell::ms, &SweepCell::hGrazing, &SweepCell::footprintMean,
                  &SweepCell::footprintMax, &SweepCell::storageFactor, &SweepCell::lodBias,
                  &SweepCell::misclassifiedMean, &SweepCell::misclassifiedError, &SweepCell::e,
                  &SweepCell::shimmer, &SweepCell::storageFactorP99})
                EXPECT_TRUE(SameBits(a.*field, b.*field)) << l << ' ' << m;
            EXPECT_EQ(a.winner, b.winner);
            EXPECT_EQ(a.pagesRequested, b.pagesRequested);
            EXPECT_EQ(a.pagesDropped, b.pagesDropped);
            EXPECT_EQ(a.phases, b.phases);
        }
    EXPECT_TRUE(SameBits(read.lights[1].light.position.y, 1e-300));
    EXPECT_TRUE(SameBits(read.lights[0].light.direction.z, std::nextafter(0.2, 1.0)));
    // -0.0 keeps its sign.
    EXPECT_TRUE(std::signbit(read.lights[0].cells[1].hGrazing));
    // Written again, the same text.
    EXPECT_EQ(SweepRecordText(read), text);
}

// Shards measured along different camera-path lengths are not one sweep.
TEST(SweepRecord, IdentityNamesTheShimmerPoses) {
    const SweepIdentity a = WholeRecord(1).identity;
    SweepIdentity b = a;
    b.shimmerPoses = 0;
    EXPECT_EQ(IdentityDifference(a, b), "shimmer poses ('3' vs '0')");
    EXPECT_EQ(IdentityDifference(a, a), "");
}

// ... nor shards measured with a different most phases (adaptive phases: --max-phases).
TEST(SweepRecord, IdentityNamesTheMostPhases) {
    const SweepIdentity a = WholeRecord(1).identity;
    SweepIdentity b = a;
    b.maxPhases = 16;
    EXPECT_EQ(IdentityDifference(a, b), "max phases ('64' vs '16')");
}

TEST(SweepRecord, ShardsMergeIntoTheWholeRecord) {
    const SweepRecord whole = WholeRecord(7);
    std::vector<SweepRecord> shards;
    for (std::size_t k : {2u, 0u, 1u}) {  // any order
        SweepRecord shard = whole;
        shard.shard = {k, 3};
        shard.lights.clear();
        shard.study[0].clear();
        shard.seconds = 0.5;
        for (std::size_t i : ShardLights(7, shard.shard)) {
            shard.lights.push_back(whole.lights[i]);
            shard.study[0].push_back(whole.study[0][i]);
        }
        // Through the text, as lexel merge reads them.
        shards.push_back(ParseSweepRecord(SweepRecordText(shard), "shard"));
    }
    const MergedSweep merged = MergeRecords(shards, {"s2", "s0", "s1"});
    EXPECT_EQ(SweepRecordText(merged.record), SweepRecordText(whole));
    EXPECT_EQ(merged.result.indices, (std::vector<std::size_t>{0, 1, 2, 3, 4, 5, 6}));
}

TEST(SweepRecord, MergeNamesOverlappingAndMissingLights) {
    const SweepRecord whole = WholeRecord(4);
    SweepRecord first = whole, second = whole;
    first.lights = {whole.lights[0], whole.lights[1]};
    first.study[0] = {whole.study[0][0], whole.study[0][1]};
    second.lights = {whole.lights[1]};
    second.study[0] = {whole.study[0][1]};
    try {
        MergeRecords({first, second}, {"a", "b"});
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "merge: light 1 is in both a and b (overlapping shards)");
    }
    try {
        MergeRecords({first}, {"a"});
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(
            e.what(),
            "merge: lights 2 and 3 of 4 are in none of the shards given (missing shards?)");
    }
    SweepRecord other = whole;
    other.identity.caseHash = "fedcba9876543210";
    try {
        MergeRecords({whole, other}, {"a", "b"});
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(),
                     "merge: b is not a shard of the sweep of a: they differ in case file (FNV-1a "
                     "64 of its bytes) ('0123456789abcdef' vs 'fedcba9876543210')");
    }
}

TEST(SweepRecord, ADamagedRecordNamesTheField) {
    std::string text = SweepRecordText(WholeRecord(2));
    const std::size_t at = text.find("\"receiver_pixels\":11166");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 23, "\"receiver_pixels\":-4");
    try {
        ParseSweepRecord(text, "r.json");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("r.json: /lights/1/receiver_pixels: ", 0), 0u)
            << e.what();
    }
}

TEST(SweepJournal, LinesReadBackIntoTheFinishedLights) {
    const SweepRecord whole = WholeRecord(2);
    const JournalHeader header =
        ParseJournalHeader(JournalHeaderLine(whole.identity, {1, 4}), "j:1");
    EXPECT_EQ(header.identity, whole.identity);
    EXPECT_EQ(header.shard, (SweepShard{1, 4}));
    SweepDone done;
    std::string line = JournalLightLine(whole.lights[1]);
    line.pop_back();  // the '\n'
    ParseJournalEntry(line, "j:2", 2, 1, done);
    std::string study = JournalStudyLine({4, 1, {41.0625}});
    study.pop_back();
    ParseJournalEntry(study, "j:3", 2, 1, done);
    ASSERT_EQ(done.lights.count(1), 1u);
    EXPECT_EQ(done.lights[1].receiverPixels, 11166);
    EXPECT_EQ(done.lights[1].cells[1].h, whole.lights[1].cells[1].h);
    EXPECT_EQ(done.lights[1].cells[1].winner, "lispsm-tight");
    EXPECT_TRUE(std::isnan(done.lights[1].cells[0].footprintMean));
    EXPECT_EQ(done.study.at({4, 1}).misclassified, std::vector<double>{41.0625});
}

// A scratch directory of this test, removed after it.
class SweepJournalFile : public ::testing::Test {
  protected:
    void SetUp() override { ASSERT_FALSE(dir_.empty()); }
    // The message of the InputError that making a journal at `path` throws, or "no error".
    static std::string Refusal(const fs::path& path, bool resume, SweepShard shard = {}) {
        try {
            const SweepJournal journal(path, WholeRecord(3).identity, shard, resume);
        } catch (const InputError& e) {
            return e.what();
        }
        return "no error";
    }
    const test::ScratchDirectory scratch_{"lexel_journal_test"};
    const fs::path dir_ = scratch_.Path();
};

// Before: a link at the journal's path was followed, its target truncated and then the link
// removed, so a user's file was lost.
TEST_F(SweepJournalFile, ALinkAtItsPathIsRefusedAndItsTargetKept) {
    const fs::path target = dir_ / "precious.txt";
    std::ofstream(target) << "a user's file\n";
    const fs::path path = SweepJournal::PathFor(dir_ / "out");
    fs::create_symlink(target, path);
    for (const bool resume : {false, true})
        EXPECT_EQ(Refusal(path, resume),
                  "--out: " + path.string() +
                      ": is a symbolic link (lexel opens no file beside --out through a link; "
                      "remove it)");
    std::ifstream in(target);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "a user's file\n");
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(path)));
    // A dangling link too (before: exit 1).
    fs::remove(target);
    EXPECT_NE(Refusal(path, false).find(": is a symbolic link"), std::string::npos);
}

// Before: --resume blocked for ever on a FIFO, read a link to /dev/zero without a cap, and a
// directory exited 1.
TEST_F(SweepJournalFile, AFifoADirectoryOrAMissingParentIsRefusedAtOnce) {
    const fs::path fifo = SweepJournal::PathFor(dir_ / "fifo");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(Refusal(fifo, true),
              "--out: " + fifo.string() + ": is a FIFO (named pipe), not a resume journal");
    const fs::path folder = SweepJournal::PathFor(dir_ / "folder");
    fs::create_directory(folder);
    EXPECT_EQ(Refusal(folder, true),
              "--out: " + folder.string() + ": is a directory, not a resume journal (remove it)");
    const fs::path file = dir_ / "file";
    std::ofstream(file) << "x";
    EXPECT_EQ(Refusal(file / ".j", false),
              "--out: " + (file / ".j").string() +
                  ": cannot create the resume journal (Not a directory)");
    EXPECT_TRUE(fs::is_fifo(fifo));
    EXPECT_TRUE(fs::is_directory(folder));
}

// Before: a journal was read whole however large.
TEST_F(SweepJournalFile, OneLargerThanTheCapIsRefusedUnread) {
    const fs::path path = SweepJournal::PathFor(dir_ / "big");
    { std::ofstream(path) << "x"; }
    fs::resize_file(path, kMaxSweepJournalBytes + 1);  // sparse: no disk taken
    EXPECT_EQ(Refusal(path, true), "--resume: " + path.string() + ": larger than " +
                                       std::to_string(kMaxSweepJournalBytes) +
                                       " bytes, the most a resume journal may be");
    EXPECT_EQ(fs::file_size(path), kMaxSweepJournalBytes + 1);  // left as it is
}

// Before: journal lines for lights outside the sweep counted as "done".
TEST_F(SweepJournalFile, LinesForLightsOutsideTheShardAreRefused) {
    const SweepRecord whole = WholeRecord(3);
    const fs::path path = SweepJournal::PathFor(dir_ / "share");
    const auto write = [&](const SweepLightRecord& light) {
        std::ofstream(path) << JournalHeaderLine(whole.identity, {0, 2}) << JournalLightLine(light);
    };
    write(whole.lights[2]);  // light 2 is shard 0/2's
    EXPECT_EQ(Refusal(path, true, {0, 2}), "no error");
    write(whole.lights[1]);
    EXPECT_EQ(Refusal(path, true, {0, 2}),
              "--resume: " + path.string() +
                  ":2: light 1 is not in this run's lights (shard 0/2 of 3 lights): a damaged "
                  "journal");
    SweepLightRecord beyond = whole.lights[2];
    beyond.index = 4;
    write(beyond);
    EXPECT_NE(Refusal(path, true, {0, 2}).find(":2: light 4 is not in this run's lights"),
              std::string::npos);
}

// Before: a full disk when the journal was made left an empty journal behind.
TEST_F(SweepJournalFile, OneThatCannotBeWrittenIsRemoved) {
    const fs::path path = SweepJournal::PathFor(dir_ / "full");
    struct rlimit before {};
    ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &before), 0);
    const auto previous = std::signal(SIGXFSZ, SIG_IGN);  // a write past the limit fails, EFBIG
    struct rlimit limit = before;
    limit.rlim_cur = 16;
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &limit), 0);
    std::string error = "no error";
    try {
        const SweepJournal journal(path, WholeRecord(3).identity, {}, false);
    } catch (const std::runtime_error& e) {
        error = e.what();
    }
    ::setrlimit(RLIMIT_FSIZE, &before);
    std::signal(SIGXFSZ, previous);
    EXPECT_EQ(error, path.string() + ": cannot write the resume journal (File too large)");
    EXPECT_FALSE(fs::exists(fs::symlink_status(path)));
}

// A run, merge or storage into DIR and a sweep into DIR never run at once, in either order; the
// empty journal a SweepExclusion made is gone after it, and a sweep's is kept.
TEST_F(SweepJournalFile, ASweepAndAnotherCommandIntoOneDirectoryExcludeEachOther) {
    const fs::path out = dir_ / "out";
    const fs::path path = SweepJournal::PathFor(out);
    const std::string held =
        "--out: another lexel command writing into this directory is "
        "running (it holds the resume journal " +
        path.string() + ")";
    {
        const SweepExclusion run(out);
        const SweepExclusion merge(out);  // two non-sweeps may share DIR, as before
        EXPECT_TRUE(fs::is_regular_file(path));
        EXPECT_EQ(Refusal(path, false), held);
    }
    EXPECT_FALSE(fs::exists(path));
    {
        const SweepJournal sweep(path, WholeRecord(3).identity, {}, false);
        try {
            const SweepExclusion run(out);
            ADD_FAILURE() << "a run while a sweep holds the journal";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()), held);
        }
    }
    // A killed sweep's journal (with lines) outlives a run into DIR.
    std::ofstream(path) << JournalHeaderLine(WholeRecord(3).identity, {});
    { const SweepExclusion run(out); }
    EXPECT_GT(fs::file_size(path), 0u);
    // A link at the path is refused, not followed.
    fs::remove(path);
    fs::create_symlink(dir_ / "elsewhere", path);
    EXPECT_THROW(SweepExclusion{out}, InputError);
    EXPECT_FALSE(fs::exists(dir_ / "elsewhere"));
}

}  // namespace
}  // namespace lexel::cases
