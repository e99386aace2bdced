/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureSMP.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureSMP
 * @brief   vtkSMPTools::For on all cores, also where VTK's default backend is sequential (private)
 *
 * Every parallel loop of the project goes through For(), every parallel sort through Sort(). A
 * VTK whose default vtkSMPTools backend is Sequential (Debian's ParaView 5.11: pvpython and
 * pvbatch trace on one core) runs the loop with the STDThread backend instead, which VTK 9.1
 * always builds, for that loop only (vtkSMPTools::LocalScope; its sort is serial). A backend
 * chosen in the environment (VTK_SMP_BACKEND_IN_USE) is kept, and VTK_SMP_MAX_THREADS still caps
 * the threads.
 */

#ifndef vtkApertureSMP_h
#define vtkApertureSMP_h

#include "vtkSMPTools.h"

#include <cstdlib>
#include <cstring>
#include <string>

class vtkApertureSMP
{
public:
  template <typename Functor>
  static void For(vtkIdType first, vtkIdType last, vtkIdType grain, Functor&& functor)
  {
    Run([&]() { vtkSMPTools::For(first, last, grain, functor); });
  }

  template <typename Functor>
  static void For(vtkIdType first, vtkIdType last, Functor&& functor)
  {
    Run([&]() { vtkSMPTools::For(first, last, functor); });
  }

  /// vtkSMPTools::Sort on all cores: give a strict total order, so that the result is the same
  /// whatever the backend and the number of threads.
  template <typename Iterator, typename Compare>
  static void Sort(Iterator begin, Iterator end, Compare&& compare)
  {
    Run([&]() { vtkSMPTools::Sort(begin, end, compare); });
  }

private:
  template <typename Loop>
  static void Run(Loop&& loop)
  {
    if (std::strcmp(vtkSMPTools::GetBackend(), "Sequential") != 0 ||
      std::getenv("VTK_SMP_BACKEND_IN_USE"))
    {
      loop();
      return;
    }
    vtkSMPTools::LocalScope(vtkSMPTools::Config{ std::string("STDThread") }, loop);
  }
};

#endif
// VTK-HeaderTest-Exclude: vtkApertureSMP.h
