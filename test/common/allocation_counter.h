/*!
  \file allocation_counter.h
  \brief Counts heap allocations in a scope, for the "no per-frame allocation" tests.

  Linking a test that uses sslt::AllocationCounter pulls allocation_counter.cpp, which replaces the global
  operator new of that test binary only (a static-library object is linked when referenced).
*/
#ifndef SSL_ALLOCATION_COUNTER_H
#define SSL_ALLOCATION_COUNTER_H

namespace sslt {
//! Counts the global operator new calls made between its construction and count().
class AllocationCounter
{
public:
  AllocationCounter();  //!< Starts counting from zero.
  ~AllocationCounter(); //!< Stops counting.
  long count() const;   //!< Allocations since construction.
};
} // namespace sslt

#endif
