// FlatEdgeMap / FlatEdgeSet (the unfolder's edge tables since 2026-12-05) against
// std::map / std::set fed the same operations: random directed and undirected pairs with
// repeats, ids -1 and large ones, values overwritten and incremented through operator[],
// lookups of absent keys, growth from empty and from reserve(), and every key visited once by
// ForEach / Keys().
#include "CoreTestUtilities.h"
#include "FlatEdgeHash.h"

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace
{
using Pair = std::pair<int, int>;

void CompareMap(int keys, int range, size_t reserve, unsigned seed)
{
  const std::string name = "map, " + std::to_string(keys) + " operations, ids < " +
    std::to_string(range) + ", reserve " + std::to_string(reserve);
  std::mt19937 rng(seed);
  auto id = [&]() { return static_cast<int>(rng() % (range + 1)) - 1; }; // -1 .. range - 1
  foldingmeshes::FlatEdgeMap<int> flat;
  flat.reserve(reserve);
  std::map<Pair, int> expected;
  for (int i = 0; i < keys; ++i)
  {
    const Pair e{ id(), id() };
    if (rng() % 3 == 0)
    {
      ++flat[e];
      ++expected[e];
    }
    else
    {
      flat[e] = i;
      expected[e] = i;
    }
    const Pair probe{ id(), id() };
    const int* found = flat.find(probe);
    const auto it = expected.find(probe);
    EXPECT((found != nullptr) == (it != expected.end()) && (!found || *found == it->second),
      name << ": lookup of (" << probe.first << ", " << probe.second << ") after " << i + 1);
  }
  EXPECT(flat.size() == expected.size(),
    name << ": " << flat.size() << " keys, the map " << expected.size());
  std::vector<std::pair<Pair, int>> visited;
  flat.ForEach([&](const Pair& e, int value) { visited.push_back({ e, value }); });
  std::sort(visited.begin(), visited.end());
  const std::vector<std::pair<Pair, int>> all(expected.begin(), expected.end());
  EXPECT(visited == all, name << ": ForEach does not visit the map's keys and values");
  for (const auto& entry : expected)
    EXPECT(flat.count(entry.first) == 1,
      name << ": (" << entry.first.first << ", " << entry.first.second << ") not counted");
}

void CompareSet(int keys, int range, unsigned seed)
{
  const std::string name = "set, " + std::to_string(keys) + " inserts";
  std::mt19937 rng(seed);
  foldingmeshes::FlatEdgeSet flat;
  std::set<Pair> expected;
  for (int i = 0; i < keys; ++i)
  {
    const int a = static_cast<int>(rng() % range), b = static_cast<int>(rng() % range);
    const Pair e{ std::min(a, b), std::max(a, b) };
    const bool fresh = expected.insert(e).second;
    EXPECT(flat.insert(e) == fresh, name << ": insert " << i << " says new = " << !fresh);
  }
  std::vector<Pair> members = flat.Keys();
  std::sort(members.begin(), members.end());
  EXPECT(members == std::vector<Pair>(expected.begin(), expected.end()),
    name << ": Keys() are not the set's members");
  EXPECT(flat.count({ range, range }) == 0, name << ": counts a pair never inserted");
  flat.clear();
  EXPECT(flat.empty() && flat.count(*expected.begin()) == 0, name << ": clear() left members");
}
}

int main()
{
  foldingmeshes::FlatEdgeMap<int> empty;
  EXPECT(empty.find({ 0, 0 }) == nullptr && empty.count({ -1, -1 }) == 0 && empty.empty(),
    "an empty map finds nothing");
  CompareMap(0, 10, 0, 1);
  CompareMap(5, 3, 0, 2);
  CompareMap(2000, 40, 0, 3);      // many repeats: most operations hit a key
  CompareMap(20000, 100000, 0, 4); // grows from 16 slots many times
  CompareMap(3000, 1000, 5000, 5); // reserved: no growth
  CompareSet(0, 5, 6);
  CompareSet(500, 20, 7);
  CompareSet(50000, 3000, 8);
  return coretest::Finish("TestFlatEdgeHash");
}
