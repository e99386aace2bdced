/*=========================================================================

  Program:   ApertureLighting
  Module:    aperture-render.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// aperture-render: a mesh or a height field (by default the embedded Mount Fuji tile) under
// suns, sphere lights and a sky, with ambient aperture lighting. See --help.
//
// What it tells the user goes to stdout; a failure is one line on stderr and a non-zero exit
// status (1 for input that cannot be used, 2 for a malformed command line).

#include "ApertureRenderCache.h"
#include "ApertureRenderInput.h"
#include "ApertureRenderMessages.h"
#include "ApertureRenderOptions.h"
#include "ApertureRenderView.h"

#include "vtkAperturePrecompute.h"
#include "vtkApertureText.h"
#include "vtkDataSet.h"
#include "vtkVersion.h"
#include "vtksys/SystemTools.hxx"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <iostream>

namespace
{
ApertureRender::MessageCapture* Messages = nullptr;

// VTK 9.1 calls abort() on some failures (an X server that goes away, no usable visual): report
// the error it gave, in one line, rather than die silently.
extern "C" void OnAbort(int)
{
  std::cout.flush();
  std::string line = "aperture-render: VTK stopped the program";
  const std::string reason = Messages ? Messages->LastError() : std::string();
  line += reason.empty() ? std::string(".\n") : ": " + vtkApertureText::Line(reason) + "\n";
  if (write(STDERR_FILENO, line.data(), line.size()) < 0)
  {
    _exit(1); // nothing more can be said
  }
  _exit(1);
}

// Messages quote file names and content: each is printed as one safe line (vtkApertureText).
int Fail(const std::string& message, int code)
{
  std::cerr << "aperture-render: " << vtkApertureText::Line(message) << "\n";
  return code;
}

void Say(const std::string& line)
{
  std::cout << vtkApertureText::Line(line) << "\n";
}

// An output file's extension must be one of `extensions` and its folder must exist.
bool CheckOutput(const std::string& option, const std::string& path,
  const std::vector<std::string>& extensions, std::string& error)
{
  const std::string extension =
    vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(path));
  if (std::find(extensions.begin(), extensions.end(), extension) == extensions.end())
  {
    error = option + " " + vtkApertureText::QuoteName(path) + " must end in";
    for (const std::string& e : extensions)
    {
      error += " " + e;
    }
    return false;
  }
  const std::string folder =
    vtksys::SystemTools::GetFilenamePath(vtksys::SystemTools::CollapseFullPath(path));
  if (!vtksys::SystemTools::FileIsDirectory(folder))
  {
    error = option + " " + vtkApertureText::QuoteName(path) + ": the folder " +
      vtkApertureText::QuoteName(folder) + " does not exist";
    return false;
  }
  return true;
}
}

int main(int argc, char* argv[])
{
  using namespace ApertureRender;
  MessageCapture messages;
  Messages = &messages;
  std::signal(SIGABRT, OnAbort);
  Options options;
  std::string error;
  if (const int code = ParseOptions(argc, argv, options, error))
  {
    return Fail(error, code);
  }
  if (options.Help)
  {
    std::cout << HelpText();
    return 0;
  }
  if (options.Version)
  {
    std::cout << "aperture-render " APERTURE_RENDER_VERSION " (ApertureLighting, VTK "
              << vtkVersion::GetVTKVersion() << ")\n";
    return 0;
  }
  if ((!options.Output.empty() && !CheckOutput("-o", options.Output, { ".png" }, error)) ||
    (!options.SaveData.empty() &&
      !CheckOutput("--save-data", options.SaveData, { ".vtp", ".vti" }, error)) ||
    (!options.Cache.empty() && !CheckOutput("--cache", options.Cache, { ".vtp", ".vti" }, error)))
  {
    return Fail(error, 2);
  }

  Input input;
  if (!LoadInput(options, messages, input, error) ||
    !LoadEnvironment(options, messages, input, error))
  {
    return Fail(error, 1);
  }
  const bool field = input.Heights != nullptr;
  const bool rays = !field || options.RaysGiven;
  if (field)
  {
    // Rays cost per sample: resample first. Horizons take the whole grid, up to the largest
    // texture OpenGL implementations commonly have (16384), which shades the drawn mesh.
    Resample(input, rays ? options.MaximumGrid : 16384);
  }
  const std::string wanted = field ? ".vti" : ".vtp";
  auto extension = [](const std::string& path)
  { return vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(path)); };
  if (!options.Cache.empty() && extension(options.Cache) != wanted)
  {
    return Fail(
      "--cache for " + std::string(field ? "a height field" : "a mesh") + " must end in " + wanted,
      2);
  }
  if (!options.SaveData.empty() && !field && extension(options.SaveData) == ".vti")
  {
    return Fail("--save-data: a mesh is written as .vtp (.vti is for height fields)", 2);
  }
  Say(input.Description);
  for (const std::string& note : input.Notes)
  {
    Say("note: " + note);
  }

  // The apertures: from the cache when it was made for this input, else cast.
  const std::string fingerprint = Fingerprint(input, options);
  vtkSmartPointer<vtkDataObject> apertures;
  if (!options.Cache.empty())
  {
    std::string note;
    apertures = ReadCache(options.Cache, fingerprint, field, messages, note);
    if (!note.empty())
    {
      Say("note: " + note);
    }
    if (apertures)
    {
      Say("apertures: read from the cache " + vtkApertureText::QuoteName(options.Cache));
    }
  }
  if (!apertures)
  {
    vtkNew<vtkAperturePrecompute> precompute;
    if (field)
    {
      precompute->SetInputData(input.Heights);
    }
    else
    {
      precompute->SetInputData(input.Mesh);
    }
    precompute->SetNumberOfRays(options.Rays);
    precompute->SetNumberOfSectors(options.Sectors);
    if (rays)
    {
      precompute->SetMethodToRays();
    }
    precompute->SetHeightScale(options.HeightScale);
    precompute->SetFeatureAngle(options.Crease);
    precompute->SetMaximumEdgeLength(input.MaximumEdge);
    precompute->ComputeAmbientOcclusionOn();
    messages.Clear();
    const auto start = std::chrono::steady_clock::now();
    {
      ProgressBar bar(precompute, "apertures");
      precompute->Update();
    }
    const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
    if (!messages.FirstError().empty())
    {
      return Fail("cannot compute the apertures: " + messages.FirstError(), 1);
    }
    apertures = precompute->GetOutputDataObject(0);
    const vtkIdType points = vtkDataSet::SafeDownCast(apertures)->GetNumberOfPoints();
    std::cout << "apertures: " << points << " points x "
              << (rays ? std::to_string(options.Rays) + " rays"
                       : std::to_string(options.Sectors) + " horizon sectors")
              << " in " << seconds.count() << " s\n";
    if (!options.Cache.empty())
    {
      if (!WriteCache(options.Cache, apertures, fingerprint, messages, error))
      {
        return Fail(error, 1);
      }
      Say("apertures: cached in " + vtkApertureText::QuoteName(options.Cache));
    }
  }

  View view(options, input, apertures);
  if (!view.Open(error))
  {
    return Fail(error, 1);
  }
  Say(view.Description());
  if (!options.SaveData.empty())
  {
    if (!view.WriteData(options.SaveData, messages, error))
    {
      return Fail(error, 1);
    }
    Say("data: " + vtksys::SystemTools::CollapseFullPath(options.SaveData));
  }
  if (!options.Output.empty())
  {
    if (!view.WritePicture(options.Output, messages, error))
    {
      return Fail(error, 1);
    }
    Say("wrote " + vtksys::SystemTools::CollapseFullPath(options.Output));
  }
  if (options.Interactive)
  {
    view.Interact();
  }
  return 0;
}
