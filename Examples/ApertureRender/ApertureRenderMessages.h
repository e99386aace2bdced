/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderMessages.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// aperture-render's messages: VTK's errors and warnings collected instead of printed, so that
// a failure is reported in one line, and a progress bar on the terminal.

#ifndef ApertureRenderMessages_h
#define ApertureRenderMessages_h

#include "vtkCallbackCommand.h" // For vtkCallbackCommand
#include "vtkNew.h"

#include <chrono>
#include <string>
#include <vector>

class vtkAlgorithm;

namespace ApertureRender
{
// While it exists, VTK's errors and warnings are kept here rather than printed. It also silences
// vtkLogger on stderr for the rest of the program (aperture-render keeps one for its whole run).
class MessageCapture
{
public:
  MessageCapture();
  ~MessageCapture();
  MessageCapture(const MessageCapture&) = delete;
  MessageCapture& operator=(const MessageCapture&) = delete;

  // The first error since the last Clear(), as one sentence without VTK's file, line and object
  // address; empty when there is none.
  std::string FirstError() const;
  // FirstError(), or `fallback` when there is none.
  std::string FirstErrorOr(const std::string& fallback) const;
  std::string LastError() const;
  const std::vector<std::string>& Warnings() const { return this->WarningTexts; }
  void Clear();

private:
  static void OnMessage(vtkObject*, unsigned long event, void* clientData, void* callData);
  vtkNew<vtkCallbackCommand> Callback;
  unsigned long ErrorTag = 0, WarningTag = 0;
  int SavedDisplayMode = 0;
  std::vector<std::string> ErrorTexts, WarningTexts;
};

// A progress bar on stderr for an algorithm's ProgressEvents, drawn only on a terminal.
class ProgressBar
{
public:
  ProgressBar(vtkAlgorithm* algorithm, const std::string& label);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

private:
  static void OnProgress(vtkObject*, unsigned long, void* clientData, void* callData);
  vtkAlgorithm* Algorithm;
  std::string Label;
  vtkNew<vtkCallbackCommand> Callback;
  unsigned long Tag = 0;
  bool Terminal;
  bool Drawn = false;
  std::chrono::steady_clock::time_point Start;
};
}

#endif
