// Hash set and map keyed by a pair of point ids (an edge, directed or not), stored flat: open
// addressing with linear probing in one array, so that building one over every edge of a
// mesh makes no allocation per edge (the unfolder's seam and hole passes build several per
// run; node-based std::unordered_* spent about a fifth of an unfold in malloc and free).
#ifndef foldingmeshes_FlatEdgeHash_h
#define foldingmeshes_FlatEdgeHash_h

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace foldingmeshes
{
namespace flat_edge_detail
{
/// The pair as one 64-bit key; the empty slot is a key no pair of ids >= -1 makes.
inline uint64_t Pack(const std::pair<int, int>& e)
{
  return (static_cast<uint64_t>(static_cast<uint32_t>(e.first)) << 32) |
    static_cast<uint32_t>(e.second);
}
inline std::pair<int, int> Unpack(uint64_t key)
{
  return { static_cast<int>(static_cast<uint32_t>(key >> 32)),
    static_cast<int>(static_cast<uint32_t>(key)) };
}
constexpr uint64_t EmptyKey = 0x8000000080000000ull; // (INT_MIN, INT_MIN)
inline size_t Mix(uint64_t key)
{
  key ^= key >> 33;
  key *= 0xff51afd7ed558ccdull;
  key ^= key >> 33;
  return static_cast<size_t>(key);
}
}

/**
 * Map from a pair of ints to Value (default-constructed on first access with operator[]).
 * Lookups and inserts only - no erase; iteration (ForEach) is in slot order, which callers
 * must not depend on (sort what they collect). Pairs of INT_MIN are not allowed as keys.
 */
template <typename Value>
class FlatEdgeMap
{
public:
  /// Room for n keys without growing.
  void reserve(size_t n)
  {
    size_t capacity = 16;
    while (capacity < 2 * n)
      capacity *= 2;
    if (capacity > this->Keys.size())
      this->Rehash(capacity);
  }
  size_t size() const { return this->Count; }
  bool empty() const { return this->Count == 0; }
  void clear()
  {
    this->Keys.clear();
    this->Values.clear();
    this->Count = 0;
  }

  Value& operator[](const std::pair<int, int>& e)
  {
    if (2 * (this->Count + 1) > this->Keys.size())
      this->Rehash(this->Keys.empty() ? 16 : 2 * this->Keys.size());
    const uint64_t key = flat_edge_detail::Pack(e);
    size_t i = this->Slot(key);
    if (this->Keys[i] == flat_edge_detail::EmptyKey)
    {
      this->Keys[i] = key;
      this->Values[i] = Value();
      ++this->Count;
    }
    return this->Values[i];
  }
  /// The value of e, or nullptr.
  const Value* find(const std::pair<int, int>& e) const
  {
    if (this->Keys.empty())
      return nullptr;
    const size_t i = this->Slot(flat_edge_detail::Pack(e));
    return this->Keys[i] == flat_edge_detail::EmptyKey ? nullptr : &this->Values[i];
  }
  size_t count(const std::pair<int, int>& e) const { return this->find(e) ? 1 : 0; }
  /// visit(key, value) for every key, in slot order.
  template <typename Visit>
  void ForEach(Visit visit) const
  {
    for (size_t i = 0; i < this->Keys.size(); ++i)
      if (this->Keys[i] != flat_edge_detail::EmptyKey)
        visit(flat_edge_detail::Unpack(this->Keys[i]), this->Values[i]);
  }

private:
  /// The slot holding key, or the empty slot where it would go.
  size_t Slot(uint64_t key) const
  {
    const size_t mask = this->Keys.size() - 1;
    size_t i = flat_edge_detail::Mix(key) & mask;
    while (this->Keys[i] != key && this->Keys[i] != flat_edge_detail::EmptyKey)
      i = (i + 1) & mask;
    return i;
  }
  void Rehash(size_t capacity)
  {
    std::vector<uint64_t> keys(capacity, flat_edge_detail::EmptyKey);
    std::vector<Value> values(capacity);
    std::swap(keys, this->Keys);
    std::swap(values, this->Values);
    for (size_t i = 0; i < keys.size(); ++i)
      if (keys[i] != flat_edge_detail::EmptyKey)
      {
        const size_t j = this->Slot(keys[i]);
        this->Keys[j] = keys[i];
        this->Values[j] = std::move(values[i]);
      }
  }

  std::vector<uint64_t> Keys; ///< EmptyKey: a free slot
  std::vector<Value> Values;
  size_t Count = 0;
};

/// Set of pairs of ints, as FlatEdgeMap (insert and count; Keys() in slot order).
class FlatEdgeSet
{
public:
  void reserve(size_t n) { this->Map.reserve(n); }
  size_t size() const { return this->Map.size(); }
  bool empty() const { return this->Map.empty(); }
  void clear() { this->Map.clear(); }
  /// True when e was not in the set.
  bool insert(const std::pair<int, int>& e)
  {
    const size_t before = this->Map.size();
    this->Map[e] = 1;
    return this->Map.size() != before;
  }
  size_t count(const std::pair<int, int>& e) const { return this->Map.count(e); }
  /// The members, in slot order (sort them where the order matters).
  std::vector<std::pair<int, int>> Keys() const
  {
    std::vector<std::pair<int, int>> keys;
    keys.reserve(this->Map.size());
    this->Map.ForEach([&](const std::pair<int, int>& e, char) { keys.push_back(e); });
    return keys;
  }

private:
  FlatEdgeMap<char> Map;
};
}

#endif
