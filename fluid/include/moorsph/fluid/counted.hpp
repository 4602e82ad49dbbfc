#pragma once
// Counts the constructions of a type. Effects and pair terms derive from it so a
// test can show that an effect a scene did not name was never constructed
// (DESIGN.md section 5).
#include <atomic>

namespace moorsph::fluid {

template <class T>
class Counted {
 public:
  Counted() { ++counter(); }
  Counted(const Counted&) { ++counter(); }
  Counted& operator=(const Counted&) = default;
  static long constructed() { return counter().load(); }

 private:
  static std::atomic<long>& counter() {
    static std::atomic<long> c{0};
    return c;
  }
};

}  // namespace moorsph::fluid
