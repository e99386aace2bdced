/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureMemory.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureMemory
 * @brief   big buffers first touched cheaply (private)
 *
 * A buffer of hundreds of megabytes is first touched page by page; on virtual machines each
 * fault costs more than writing the page. Where Linux gives transparent huge pages on request
 * (`madvise` mode, Debian's default), AdviseHugePages() asks for them: 512 times fewer faults.
 * Elsewhere it does nothing. Reserve() and Assign() are std::vector's, on storage so advised:
 * the intake of a mesh of millions of triangles spent half its time in page faults.
 */

#ifndef vtkApertureMemory_h
#define vtkApertureMemory_h

#include <cstddef>
#include <cstdint>
#include <vector>

#ifdef __linux__
#include <sys/mman.h>
#endif

namespace vtkApertureMemory
{
/// Asks for huge pages over the whole pages inside [data, data + bytes), before they are touched.
inline void AdviseHugePages(void* data, size_t bytes)
{
#ifdef __linux__
  const uintptr_t page = 4096;
  const uintptr_t begin = (reinterpret_cast<uintptr_t>(data) + page - 1) & ~(page - 1);
  const uintptr_t end = (reinterpret_cast<uintptr_t>(data) + bytes) & ~(page - 1);
  if (end > begin + (uintptr_t(2) << 20))
  {
    madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
  }
#else
  (void)data;
  (void)bytes;
#endif
}

/// v.reserve(n), new storage advised before it is touched (the elements kept).
template <typename T>
void Reserve(std::vector<T>& v, size_t n)
{
  if (n <= v.capacity())
  {
    return;
  }
  std::vector<T> fresh;
  fresh.reserve(n);
  AdviseHugePages(fresh.data(), n * sizeof(T));
  fresh.insert(fresh.end(), v.begin(), v.end());
  v.swap(fresh);
}

/// v.assign(n, value) on storage advised before it is touched.
template <typename T, typename Value = T>
void Assign(std::vector<T>& v, size_t n, const Value& value = Value())
{
  const T copy = static_cast<T>(value); // `value` may be an element of v
  if (n > v.capacity())
  {
    std::vector<T>().swap(v);
  }
  Reserve(v, n);
  v.assign(n, copy);
}
}

#endif
// VTK-HeaderTest-Exclude: vtkApertureMemory.h
