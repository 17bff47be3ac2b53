// Files made on several threads and put in place in the order given
// (orb/job/ordered_writes.h, the frame writer of orb-render --frames): the
// order, the bound on writes in flight, a failure's report and what follows
// it, and a writer ended with writes still in flight.
#include "orb/job/ordered_writes.h"

#include "job_test_support.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;
using orb::job::OrderedWrites;
using orb::job::test::FileOutput;

// What the writes saw, shared by all of them.
struct Record {
    std::mutex mutex;
    std::vector<std::string> events;  // "written 3", "not written 4: why", in the order they happened
    std::atomic<int> alive{0}, making{0}, most_alive{0}, most_making{0};

    void add(const std::string& event) {
        const std::lock_guard<std::mutex> lock(mutex);
        events.push_back(event);
    }
    static void raise(std::atomic<int>& most, int value) {
        int seen = most.load();
        while (value > seen && !most.compare_exchange_weak(seen, value)) {
        }
    }
};

// A write whose bytes are "frame N", made after `delay`; `before_make`
// may throw (an encoder's failure).
class TestWrite final : public OrderedWrites::Write {
public:
    TestWrite(Record& record, int number, const std::string& path, std::chrono::milliseconds delay,
              std::function<void()> before_make = {})
        : record_(record), number_(number), output_(path), delay_(delay), before_make_(std::move(before_make)) {
        Record::raise(record_.most_alive, ++record_.alive);
    }
    ~TestWrite() override { --record_.alive; }

    orb::job::ImageOutput& output() override { return output_; }
    std::string_view make() override {
        Record::raise(record_.most_making, ++record_.making);
        std::this_thread::sleep_for(delay_);
        --record_.making;
        if (before_make_) before_make_();
        bytes_ = "frame " + std::to_string(number_);
        return bytes_;
    }
    void written() override { record_.add("written " + std::to_string(number_)); }
    void not_written(const std::string& why) override {
        record_.add("not written " + std::to_string(number_) + (why.empty() ? "" : ": " + why));
    }

private:
    Record& record_;
    int number_;
    FileOutput output_;
    std::chrono::milliseconds delay_;
    std::function<void()> before_make_;
    std::string bytes_;
};

class OrderedWritesTest : public ::testing::Test {
protected:
    void SetUp() override {
        const char* tmp = std::getenv("TMPDIR");
        std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/orb-ordered-writes-XXXXXX";
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        folder_ = pattern;
    }
    void TearDown() override { fs::remove_all(folder_); }

    std::string path(int number) const {
        std::string name("f");  // appended, not "f" + string: GCC 12 warns falsely (-Wrestrict) on that form
        name += std::to_string(number);
        return (fs::path(folder_) / name).string();
    }
    std::vector<std::string> names() const {
        std::vector<std::string> all;
        for (const auto& entry : fs::directory_iterator(folder_)) all.push_back(entry.path().filename().string());
        std::sort(all.begin(), all.end());
        return all;
    }
    static std::string content(const std::string& file) {
        std::ifstream in(file);
        return {std::istreambuf_iterator<char>(in), {}};
    }

    std::string folder_;
    Record record_;
};

// Later writes made sooner than earlier ones are still put in place after
// them: when a write is said written, every earlier file is there and no
// later one.
TEST_F(OrderedWritesTest, FilesArePutInPlaceInTheOrderGivenWhateverOrderTheyAreMadeIn) {
    constexpr int kWrites = 8;
    std::vector<std::vector<bool>> present_when_written(kWrites);
    {
        OrderedWrites writes(4);
        for (int i = 0; i < kWrites; ++i) {
            // Each write's delay shorter than the one before it.
            writes.submit(std::make_unique<TestWrite>(record_, i, path(i), std::chrono::milliseconds(5 * (kWrites - i))));
        }
        const std::vector<OrderedWrites::Done> done = writes.take_done(/*wait=*/true);
        for (const OrderedWrites::Done& d : done) EXPECT_TRUE(d.written);
    }
    std::vector<std::string> expected;
    for (int i = 0; i < kWrites; ++i) expected.push_back("written " + std::to_string(i));
    EXPECT_EQ(record_.events, expected);
    for (int i = 0; i < kWrites; ++i) EXPECT_EQ(content(path(i)), "frame " + std::to_string(i));
    // No temporary file or lock left beside them.
    EXPECT_EQ(names().size(), static_cast<std::size_t>(kWrites));
}

TEST_F(OrderedWritesTest, EachFileIsInPlaceOnlyOnceEveryEarlierOneIs) {
    constexpr int kWrites = 6;
    std::vector<std::string> seen(kWrites);
    class Watching final : public OrderedWrites::Write {
    public:
        Watching(std::vector<std::string>& seen, int number, const std::string& path, std::function<std::vector<std::string>()> list)
            : seen_(seen), number_(number), output_(path), list_(std::move(list)) {}
        orb::job::ImageOutput& output() override { return output_; }
        std::string_view make() override {
            std::this_thread::sleep_for(std::chrono::milliseconds(3 * (6 - number_)));
            return "x";
        }
        void written() override {
            std::string files;
            for (const std::string& name : list_())
                if (name.front() != '.') files += name + " ";
            seen_[static_cast<std::size_t>(number_)] = files;
        }
        void not_written(const std::string&) override {}

    private:
        std::vector<std::string>& seen_;
        int number_;
        FileOutput output_;
        std::function<std::vector<std::string>()> list_;
    };
    {
        OrderedWrites writes(3);
        for (int i = 0; i < kWrites; ++i)
            writes.submit(std::make_unique<Watching>(seen, i, path(i), [this] { return names(); }));
    }
    std::string files;
    for (int i = 0; i < kWrites; ++i) {
        files += "f";
        files += std::to_string(i) + " ";
        EXPECT_EQ(seen[static_cast<std::size_t>(i)], files) << "when f" << i << " was said written";
    }
}

// At most `max_in_flight` writes are given and not taken back: the caller
// holds one more, the one it is about to give. Several are made at once.
TEST_F(OrderedWritesTest, WritesInFlightAreBoundedAndMadeSeveralAtOnce) {
    constexpr int kWrites = 12;
    {
        OrderedWrites writes(3);
        for (int i = 0; i < kWrites; ++i) {
            auto write = std::make_unique<TestWrite>(record_, i, path(i), std::chrono::milliseconds(20));
            writes.submit(std::move(write));  // the writes it takes back are dropped here
        }
        writes.take_done(/*wait=*/true);
        EXPECT_EQ(record_.alive.load(), 0);
    }
    EXPECT_LE(record_.most_alive.load(), 3 + 1);
    EXPECT_LE(record_.most_making.load(), 3);
    EXPECT_GE(record_.most_making.load(), 2);
    EXPECT_EQ(record_.events.size(), static_cast<std::size_t>(kWrites));
}

// An encoder's failure is said once, naming the file; the writes before it
// stay, none after it is put in place (each says so once), and no
// temporary file is left.
TEST_F(OrderedWritesTest, AFailureIsSaidOnceWithTheFileAndNothingAfterItIsPutInPlace) {
    constexpr int kWrites = 6;
    std::vector<bool> written;
    {
        OrderedWrites writes(3);
        for (int i = 0; i < kWrites; ++i) {
            std::function<void()> fail;
            if (i == 2) fail = [] { throw std::runtime_error("cannot encode the EXR (block): out of memory"); };
            writes.submit(std::make_unique<TestWrite>(record_, i, path(i), std::chrono::milliseconds(i == 2 ? 30 : 1), fail));
        }
        for (const OrderedWrites::Done& d : writes.take_done(/*wait=*/true)) written.push_back(d.written);
    }
    const std::vector<std::string> expected{
        "written 0", "written 1",
        "not written 2: " + path(2) + ": cannot write: cannot encode the EXR (block): out of memory",
        "not written 3", "not written 4", "not written 5"};
    EXPECT_EQ(record_.events, expected);
    EXPECT_EQ(names(), (std::vector<std::string>{"f0", "f1"}));
}

// A file that cannot be put in place (its folder gone once its output was
// prepared: the rename fails) is said with the file's name and why.
TEST_F(OrderedWritesTest, AFileThatCannotBePutInPlaceNamesItselfAndWhy) {
    const std::string sub = (fs::path(folder_) / "gone").string();
    fs::create_directory(sub);
    {
        OrderedWrites writes(2);
        writes.submit(std::make_unique<TestWrite>(record_, 0, path(0), std::chrono::milliseconds(1)));
        auto doomed = std::make_unique<TestWrite>(record_, 1, sub + "/f1", std::chrono::milliseconds(1));
        fs::remove_all(sub);
        writes.submit(std::move(doomed));
        writes.submit(std::make_unique<TestWrite>(record_, 2, path(2), std::chrono::milliseconds(1)));
    }
    ASSERT_EQ(record_.events.size(), 3u);
    EXPECT_EQ(record_.events[0], "written 0");
    EXPECT_EQ(record_.events[1].rfind("not written 1: " + sub + "/f1: cannot write (-o): ", 0), 0u) << record_.events[1];
    EXPECT_EQ(record_.events[2], "not written 2");
    EXPECT_EQ(names(), (std::vector<std::string>{"f0"}));
}

// A writer ended while writes are in flight (a batch stopped by an error
// elsewhere) still puts each in place, in order, before it returns.
TEST_F(OrderedWritesTest, EndingTheWriterPutsEveryWriteGivenInPlaceFirst) {
    constexpr int kWrites = 5;
    {
        OrderedWrites writes(kWrites);
        for (int i = 0; i < kWrites; ++i)
            writes.submit(std::make_unique<TestWrite>(record_, i, path(i), std::chrono::milliseconds(10)));
    }
    ASSERT_EQ(record_.events.size(), static_cast<std::size_t>(kWrites));
    for (int i = 0; i < kWrites; ++i) EXPECT_EQ(content(path(i)), "frame " + std::to_string(i));
    EXPECT_EQ(record_.alive.load(), 0);
}

// take_done without waiting gives back only the writes done, oldest first,
// stopping at the first not done.
TEST_F(OrderedWritesTest, TakingBackWithoutWaitingStopsAtTheFirstWriteNotDone) {
    std::atomic<bool> release{false};
    OrderedWrites writes(2);
    writes.submit(std::make_unique<TestWrite>(record_, 0, path(0), std::chrono::milliseconds(1)));
    writes.submit(std::make_unique<TestWrite>(record_, 1, path(1), std::chrono::milliseconds(1), [&] {
        while (!release) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }));
    std::vector<OrderedWrites::Done> first;
    for (int tries = 0; tries < 20000 && first.empty(); ++tries) {
        first = writes.take_done(/*wait=*/false);
        if (first.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    ASSERT_EQ(first.size(), 1u);
    EXPECT_TRUE(first[0].written);
    EXPECT_TRUE(writes.take_done(/*wait=*/false).empty());  // the second is still being made
    release = true;
    const std::vector<OrderedWrites::Done> second = writes.take_done(/*wait=*/true);
    ASSERT_EQ(second.size(), 1u);
    EXPECT_TRUE(second[0].written);
}

}  // namespace
