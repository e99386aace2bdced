/*=========================================================================

  Program:   ApertureLighting
  Module:    FuzzMessages.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "FuzzMessages.h"

#include "vtkApertureText.h"
#include "vtkCommand.h"
#include "vtkLogger.h"
#include "vtkObject.h"
#include "vtkOutputWindow.h"

#include <cstdlib>
#include <iostream>

FuzzMessageCheck::FuzzMessageCheck()
{
  // Messages must be built to be checked; none is printed.
  vtkObject::GlobalWarningDisplayOn();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  vtkOutputWindow* window = vtkOutputWindow::GetInstance();
  this->SavedDisplayMode = window->GetDisplayMode();
  window->SetDisplayModeToNever();
  this->Callback->SetCallback(&FuzzMessageCheck::OnMessage);
  this->ErrorTag = window->AddObserver(vtkCommand::ErrorEvent, this->Callback);
  this->WarningTag = window->AddObserver(vtkCommand::WarningEvent, this->Callback);
}

FuzzMessageCheck::~FuzzMessageCheck()
{
  vtkOutputWindow* window = vtkOutputWindow::GetInstance();
  window->RemoveObserver(this->ErrorTag);
  window->RemoveObserver(this->WarningTag);
  window->SetDisplayMode(this->SavedDisplayMode);
  vtkObject::GlobalWarningDisplayOff();
}

void FuzzMessageCheck::Require(const std::string& text, const char* what)
{
  std::size_t characters = 0;
  for (const char c : text)
  {
    characters += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  }
  if (!vtkApertureText::IsSafe(text) || characters > 500)
  {
    std::cerr << "FAIL unsafe " << what << " (" << characters
              << " characters): " << vtkApertureText::Line(text, 600) << "\n";
    std::abort();
  }
}

// VTK frames a message as "ERROR: In <source>, line N\nvtkClass (0x...): <text>\n\n"; the text
// of one raised in this project's sources is checked.
void FuzzMessageCheck::OnMessage(vtkObject*, unsigned long, void*, void* callData)
{
  const std::string message = callData ? static_cast<const char*>(callData) : "";
  const std::size_t source = message.find(": In ");
  const std::size_t header = message.find('\n');
  if (source == std::string::npos || header == std::string::npos || source > header ||
    message.compare(
      source + 5, sizeof(APERTURELIGHTING_SOURCE_DIR) - 1, APERTURELIGHTING_SOURCE_DIR) != 0)
  {
    return;
  }
  std::string text = message.substr(header + 1);
  const std::size_t address = text.find("): ");
  if (address != std::string::npos)
  {
    text = text.substr(address + 3);
  }
  text.erase(text.find_last_not_of('\n') + 1);
  Require(text, "message");
}
