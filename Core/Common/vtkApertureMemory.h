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
 * Elsewhere it does nothing.
 */

#ifndef vtkApertureMemory_h
#define vtkApertureMemory_h

#include <cstddef>
#include <cstdint>

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
}

#endif
// VTK-HeaderTest-Exclude: vtkApertureMemory.h
