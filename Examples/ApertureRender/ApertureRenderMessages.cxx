/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderMessages.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "ApertureRenderMessages.h"

#include "vtkAlgorithm.h"
#include "vtkApertureText.h"
#include "vtkCommand.h"
#include "vtkLogger.h"
#include "vtkOutputWindow.h"

#include <unistd.h>

#include <cstdio>
#include <iostream>

namespace ApertureRender
{
namespace
{
// VTK's "ERROR: In file, line N\nvtkClass (0x1234): what\n\n" as "what".
std::string Sentence(const std::string& text)
{
  std::string line = text;
  const size_t newline = line.find('\n');
  if (newline != std::string::npos && line.find(": In ") < newline)
  {
    line = newline == std::string::npos ? "" : line.substr(newline + 1);
  }
  const size_t address = line.find("): ");
  if (address != std::string::npos && line.find(" (0x") < address)
  {
    line = line.substr(address + 3);
  }
  const size_t end = line.find_last_not_of(" \n\r\t");
  line = end == std::string::npos ? "" : line.substr(0, end + 1);
  // One line: later lines of a message are details.
  return line.substr(0, line.find('\n'));
}
}

MessageCapture::MessageCapture()
{
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  vtkOutputWindow* window = vtkOutputWindow::GetInstance();
  this->SavedDisplayMode = window->GetDisplayMode();
  window->SetDisplayModeToNever();
  this->Callback->SetClientData(this);
  this->Callback->SetCallback(&MessageCapture::OnMessage);
  this->ErrorTag = window->AddObserver(vtkCommand::ErrorEvent, this->Callback);
  this->WarningTag = window->AddObserver(vtkCommand::WarningEvent, this->Callback);
}

MessageCapture::~MessageCapture()
{
  vtkOutputWindow* window = vtkOutputWindow::GetInstance();
  window->RemoveObserver(this->ErrorTag);
  window->RemoveObserver(this->WarningTag);
  window->SetDisplayMode(this->SavedDisplayMode);
}

void MessageCapture::OnMessage(vtkObject*, unsigned long event, void* clientData, void* callData)
{
  auto* self = static_cast<MessageCapture*>(clientData);
  // VTK's readers quote the files they read: the text is kept as one safe line.
  const std::string text =
    vtkApertureText::Line(Sentence(callData ? static_cast<const char*>(callData) : ""));
  (event == vtkCommand::ErrorEvent ? self->ErrorTexts : self->WarningTexts).push_back(text);
}

std::string MessageCapture::FirstError() const
{
  return this->ErrorTexts.empty() ? std::string() : this->ErrorTexts.front();
}

std::string MessageCapture::FirstErrorOr(const std::string& fallback) const
{
  const std::string error = this->FirstError();
  return error.empty() ? fallback : error;
}

std::string MessageCapture::LastError() const
{
  return this->ErrorTexts.empty() ? std::string() : this->ErrorTexts.back();
}

void MessageCapture::Clear()
{
  this->ErrorTexts.clear();
  this->WarningTexts.clear();
}

ProgressBar::ProgressBar(vtkAlgorithm* algorithm, const std::string& label)
  : Algorithm(algorithm)
  , Label(label)
  , Terminal(isatty(fileno(stderr)) != 0)
  , Start(std::chrono::steady_clock::now())
{
  this->Callback->SetClientData(this);
  this->Callback->SetCallback(&ProgressBar::OnProgress);
  this->Tag = algorithm->AddObserver(vtkCommand::ProgressEvent, this->Callback);
}

ProgressBar::~ProgressBar()
{
  this->Algorithm->RemoveObserver(this->Tag);
  if (this->Drawn)
  {
    std::cerr << "\n";
  }
}

void ProgressBar::OnProgress(vtkObject*, unsigned long, void* clientData, void* callData)
{
  auto* self = static_cast<ProgressBar*>(clientData);
  if (!self->Terminal || !callData)
  {
    return;
  }
  const double progress = *static_cast<double*>(callData);
  const int width = 40;
  const int filled = static_cast<int>(progress * width + 0.5);
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - self->Start;
  char line[160];
  std::snprintf(line, sizeof(line), "\r%s [%s%s] %3.0f%%  %.1f s", self->Label.c_str(),
    std::string(filled, '#').c_str(), std::string(width - filled, '.').c_str(), 100.0 * progress,
    elapsed.count());
  std::cerr << line << std::flush;
  self->Drawn = true;
}
}
