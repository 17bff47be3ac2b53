// for_each_block on the process's kept workers: every block exactly once,
// whoever calls (several threads at once, a body calling it again, a child
// of fork(), which has none of its parent's threads).
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstddef>
#include <thread>
#include <vector>

#include "orb/film/parallel_blocks.h"

namespace orb::film {
namespace {

// Whether for_each_block over `count` items visits each exactly once, in
// the blocks it names.
bool visits_each_once(std::size_t count) {
    std::vector<std::atomic<int>> seen(count);
    std::atomic<bool> blocks_right{true};
    for_each_block(count, [&](std::size_t block, std::size_t first, std::size_t end) {
        if (first != block * kParallelBlock || end > count || end <= first) blocks_right = false;
        for (std::size_t i = first; i < end; ++i) seen[i].fetch_add(1);
    });
    for (const std::atomic<int>& s : seen)
        if (s.load() != 1) return false;
    return blocks_right.load();
}

TEST(ParallelBlocks, VisitsEveryItemOnce) {
    for (std::size_t count : {std::size_t{0}, std::size_t{1}, kParallelBlock, kParallelBlock + 1, 5 * kParallelBlock + 7})
        EXPECT_TRUE(visits_each_once(count)) << count;
    for (int repeat = 0; repeat < 200; ++repeat) ASSERT_TRUE(visits_each_once(3 * kParallelBlock + 1)) << repeat;
}

TEST(ParallelBlocks, SeveralThreadsAtOnce) {
    std::atomic<int> wrong{0};
    std::vector<std::thread> callers;
    for (int t = 0; t < 4; ++t)
        callers.emplace_back([&] {
            for (int repeat = 0; repeat < 50; ++repeat)
                if (!visits_each_once(4 * kParallelBlock + 3)) ++wrong;
        });
    for (std::thread& c : callers) c.join();
    EXPECT_EQ(wrong.load(), 0);
}

TEST(ParallelBlocks, ABodyMayCallItAgain) {
    std::atomic<int> inner_right{0};
    for_each_block(3 * kParallelBlock, [&](std::size_t, std::size_t, std::size_t) {
        if (visits_each_once(2 * kParallelBlock + 1)) ++inner_right;
    });
    EXPECT_EQ(inner_right.load(), 3);
}

TEST(ParallelBlocks, AForkedChildHasWorkersOfItsOwn) {
    ASSERT_TRUE(visits_each_once(4 * kParallelBlock));  // the parent's workers exist
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) _exit(visits_each_once(4 * kParallelBlock) ? 0 : 1);
    // The child must finish, not wait for its parent's threads: give it 30 s.
    int status = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    pid_t done = 0;
    while ((done = waitpid(child, &status, WNOHANG)) == 0 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    if (done == 0) {
        kill(child, SIGKILL);
        waitpid(child, &status, 0);
        FAIL() << "the forked child hung in for_each_block";
    }
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0);
}

}  // namespace
}  // namespace orb::film
