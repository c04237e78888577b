// Counts heap allocations, to prove the firmware's frame loop allocates
// nothing (docs/design-brief.md, "Layers"). tests/support/heap_counter.cpp replaces the
// global operator new / delete; a test executable gets that replacement only
// when it uses heap_counter (the object file is pulled from test_support).
#pragma once

namespace test_support {

// Allocations (every form of operator new) and deallocations made since
// this counter was constructed, by any code in the process.
class heap_counter {
  public:
    heap_counter();
    long allocations() const;
    long deallocations() const;

  private:
    long m_allocations_at_start;
    long m_deallocations_at_start;
};

}  // namespace test_support
