// FreeList (util/free_list.h): objects come back in last-in, first-out order with their memory,
// an empty list makes new ones, and threads taking and giving back concurrently lose nothing.
#include <gtest/gtest.h>

#include <set>
#include <thread>
#include <vector>

#include "util/free_list.h"

namespace ontile {
namespace {

TEST(FreeList, GivesBackTheWarmestObjectWithItsMemory) {
  FreeList<std::vector<int>> list;
  EXPECT_EQ(list.take().capacity(), 0u);  // nothing kept yet: a new, empty object
  std::vector<int> first(100), second(300);
  const int* second_memory = second.data();
  list.give_back(std::move(first));
  list.give_back(std::move(second));
  const std::vector<int> taken = list.take();
  EXPECT_EQ(taken.data(), second_memory);  // the one given back last
  EXPECT_EQ(taken.size(), 300u);
  EXPECT_EQ(list.take().size(), 100u);
  EXPECT_EQ(list.take().capacity(), 0u);
}

TEST(FreeList, ConcurrentTakesAndGiveBacksKeepEveryObject) {
  FreeList<std::vector<int>> list;
  for (int i = 0; i < 8; ++i) list.give_back(std::vector<int>(1, i));
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&list] {
      for (int round = 0; round < 2000; ++round) {
        std::vector<int> item = list.take();
        if (!item.empty()) list.give_back(std::move(item));
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  std::set<int> kept;
  for (int i = 0; i < 8; ++i) kept.insert(list.take().at(0));
  EXPECT_EQ(kept, (std::set<int>{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_TRUE(list.take().empty());
}

}  // namespace
}  // namespace ontile
