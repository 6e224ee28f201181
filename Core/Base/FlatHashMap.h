// FlatHashMap: an open-addressing hash map (linear probing, one flat slot array, backward-shift erase)
// for small trivially copyable keys and values, e.g. the boundary constraints' edge and triangle keys.
// std::unordered_map allocates one node per entry; building one for a 75k-triangle surface cost more
// than the boundary recovery of that surface. Keys need operator==; Hash gives 64 bits, which are mixed
// again here (Fibonacci hashing keeps the top bits), so a plain multiplicative hash is enough.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace volgrid
{

template<class Key, class Value, class Hash>
class FlatHashMap
{
public:
  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  void clear()
  {
    slots_.clear();
    bits_ = 0;
    size_ = 0;
  }
  // Room for n entries without rehashing.
  void reserve(size_t n)
  {
    if (n > capacityFor(bits_))
      rehash(bitsFor(n));
  }

  Value* find(const Key& k) { return const_cast<Value*>(static_cast<const FlatHashMap*>(this)->find(k)); }
  const Value* find(const Key& k) const
  {
    if (slots_.empty())
      return nullptr;
    for (size_t i = home(k);; i = next(i))
    {
      const Slot& s = slots_[i];
      if (!s.used)
        return nullptr;
      if (s.key == k)
        return &s.value;
    }
  }
  bool contains(const Key& k) const { return find(k) != nullptr; }

  // The value of k, inserted as `fresh` when absent. *inserted (optional) tells which.
  Value& insert(const Key& k, const Value& fresh, bool* inserted = nullptr)
  {
    if (size_ + 1 > capacityFor(bits_))
      rehash(bitsFor(size_ + 1));
    size_t i = home(k);
    for (; slots_[i].used; i = next(i))
      if (slots_[i].key == k)
      {
        if (inserted)
          *inserted = false;
        return slots_[i].value;
      }
    slots_[i] = Slot{ k, fresh, true };
    ++size_;
    if (inserted)
      *inserted = true;
    return slots_[i].value;
  }

  // Removes k; false when absent. Later entries of the probe run are shifted back (no tombstones).
  bool erase(const Key& k)
  {
    if (slots_.empty())
      return false;
    size_t i = home(k);
    for (; slots_[i].used; i = next(i))
      if (slots_[i].key == k)
        break;
    if (!slots_[i].used)
      return false;
    for (size_t j = next(i);; j = next(j))
    {
      if (!slots_[j].used)
        break;
      // An entry may fill the hole at i only if its home is not cyclically within (i, j].
      const size_t h = home(slots_[j].key);
      const bool stays = i <= j ? (i < h && h <= j) : (i < h || h <= j);
      if (stays)
        continue;
      slots_[i] = slots_[j];
      i = j;
    }
    slots_[i].used = false;
    --size_;
    return true;
  }

private:
  struct Slot
  {
    Key key;
    Value value;
    bool used;
  };
  static size_t capacityFor(int bits) { return bits == 0 ? 0 : (size_t(1) << bits) / 8 * 5; } // load <= 5/8
  static int bitsFor(size_t n)
  {
    int b = 4;
    while (capacityFor(b) < n)
      ++b;
    return b;
  }
  size_t home(const Key& k) const
  {
    return static_cast<size_t>((static_cast<uint64_t>(Hash()(k)) * 0x9E3779B97F4A7C15ull) >> (64 - bits_));
  }
  size_t next(size_t i) const { return (i + 1) & (slots_.size() - 1); }
  void rehash(int bits)
  {
    std::vector<Slot> old;
    old.swap(slots_);
    bits_ = bits;
    slots_.assign(size_t(1) << bits, Slot{ Key(), Value(), false });
    size_ = 0;
    for (const Slot& s : old)
      if (s.used)
        insert(s.key, s.value);
  }

  std::vector<Slot> slots_;
  int bits_ = 0;
  size_t size_ = 0;
};

} // namespace volgrid
