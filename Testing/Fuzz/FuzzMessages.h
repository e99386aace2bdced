/*=========================================================================

  Program:   ApertureLighting
  Module:    FuzzMessages.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The fuzz targets' check on messages: what a hostile file makes this project say must be safe to
// print as it is, one line of valid UTF-8 without control bytes and at most a few hundred
// characters (vtkApertureText::IsSafe), since ParaView, Python and log readers show it raw.

#ifndef FuzzMessages_h
#define FuzzMessages_h

#include "vtkCallbackCommand.h" // For vtkCallbackCommand
#include "vtkNew.h"

#include <string>

// While it exists, every error and warning of the project's own classes (raised in its sources)
// is checked and the run aborted on one that is unsafe. VTK's own messages are left out: its
// readers quote files raw, and aperture-render escapes them where it forwards them.
class FuzzMessageCheck
{
public:
  FuzzMessageCheck();
  ~FuzzMessageCheck();
  FuzzMessageCheck(const FuzzMessageCheck&) = delete;
  FuzzMessageCheck& operator=(const FuzzMessageCheck&) = delete;

  // Aborts, naming `what`, unless `text` is one safe line of at most 500 characters.
  static void Require(const std::string& text, const char* what);

private:
  static void OnMessage(vtkObject*, unsigned long, void*, void* callData);
  vtkNew<vtkCallbackCommand> Callback;
  unsigned long ErrorTag = 0, WarningTag = 0;
  int SavedDisplayMode = 0;
};

#endif
