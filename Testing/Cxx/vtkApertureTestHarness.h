/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureTestHarness.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The checks the project's C++ tests share: each failed check prints one FAIL line on stderr
// and counts; Result() is the test's exit status.

#ifndef vtkApertureTestHarness_h
#define vtkApertureTestHarness_h

#include <cstdlib>
#include <iostream>
#include <string>

namespace vtkApertureTest
{
inline int& Failures()
{
  static int failures = 0;
  return failures;
}

// Checks quietly after the first 20 failures, so that a broken loop stays readable.
inline void Check(bool ok, const std::string& what)
{
  if (!ok && ++Failures() <= 20)
  {
    std::cerr << "FAIL " << what << "\n";
  }
}

inline void Check(bool ok, const std::string& what, double got, double want)
{
  if (!ok && ++Failures() <= 20)
  {
    std::cerr << "FAIL " << what << ": got " << got << ", want " << want << "\n";
  }
}

inline int Result()
{
  if (Failures() > 0)
  {
    std::cerr << Failures() << " check(s) failed\n";
  }
  return Failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}
}

#endif
// VTK-HeaderTest-Exclude: vtkApertureTestHarness.h
