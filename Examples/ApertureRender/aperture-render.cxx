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
#include "ApertureRenderVolume.h"

#include "vtkAperturePrecompute.h"
#include "vtkApertureText.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
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
  std::signal(SIGABRT, SIG_DFL); // an abort in here ends the program, not another call
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

// The command line read and the output paths checked; -1 to go on, else the exit status.
int ReadCommandLine(int argc, char* argv[], ApertureRender::Options& options)
{
  std::string error;
  if (const int code = ApertureRender::ParseOptions(argc, argv, options, error))
  {
    return Fail(error, code);
  }
  if (options.Help)
  {
    std::cout << ApertureRender::HelpText();
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
  return -1;
}

// The input and the environment read, a height field resampled for rays, and the files that
// depend on the input's kind checked; -1 to go on, else the exit status.
int ReadInput(const ApertureRender::Options& options, ApertureRender::MessageCapture& messages,
  ApertureRender::Input& input)
{
  std::string error;
  if (!ApertureRender::LoadInput(options, messages, input, error) ||
    !ApertureRender::LoadEnvironment(options, messages, input, error))
  {
    return Fail(error, 1);
  }
  if (input.Volume)
  {
    Say(input.Description);
    return options.Cache.empty() && options.SaveData.empty()
      ? -1
      : Fail("--cache and --save-data are for meshes and height fields, not volumes", 2);
  }
  const bool field = input.Heights != nullptr;
  if (field)
  {
    // Rays cost per sample: resample first. Horizons take the whole grid, up to the largest
    // texture OpenGL implementations commonly have (16384), which shades the drawn mesh.
    ApertureRender::Resample(input, options.RaysGiven ? options.MaximumGrid : 16384);
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
  return -1;
}

// The apertures cast (rays for meshes, horizon sweeps for height fields unless --rays), with a
// progress bar; null with the reason in `error` when the filter fails. Horizons (height fields,
// 4 bytes a sector and texel) and masks (meshes, 32 bytes and a ray a cell a point) are kept only
// for the modes that show them.
vtkSmartPointer<vtkDataObject> CastApertures(const ApertureRender::Options& options,
  const ApertureRender::Input& input, ApertureRender::MessageCapture& messages, std::string& error)
{
  const bool field = input.Heights != nullptr;
  const bool rays = !field || options.RaysGiven;
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
  precompute->SetComputeHorizonAngles(!rays && ApertureRender::WantsHorizons(options));
  precompute->SetComputeVisibilityMask(!field && ApertureRender::WantsMasks(options));
  messages.Clear();
  const auto start = std::chrono::steady_clock::now();
  {
    ApertureRender::ProgressBar bar(precompute, "apertures");
    precompute->Update();
  }
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  if (!messages.FirstError().empty())
  {
    error = "cannot compute the apertures: " + messages.FirstError();
    return nullptr;
  }
  vtkDataObject* apertures = precompute->GetOutputDataObject(0);
  std::cout << "apertures: " << vtkDataSet::SafeDownCast(apertures)->GetNumberOfPoints()
            << " points x "
            << (rays ? std::to_string(options.Rays) + " rays"
                     : std::to_string(options.Sectors) + " horizon sectors")
            << " in " << seconds.count() << " s\n";
  return apertures;
}

// The apertures from the cache when it was made for this input, else cast (and cached).
vtkSmartPointer<vtkDataObject> Apertures(const ApertureRender::Options& options,
  const ApertureRender::Input& input, ApertureRender::MessageCapture& messages, std::string& error)
{
  const std::string fingerprint = ApertureRender::Fingerprint(input, options);
  if (!options.Cache.empty())
  {
    std::string note;
    vtkSmartPointer<vtkDataObject> cached = ApertureRender::ReadCache(
      options.Cache, fingerprint, input.Heights != nullptr, messages, note);
    if (!note.empty())
    {
      Say("note: " + note);
    }
    if (cached)
    {
      Say("apertures: read from the cache " + vtkApertureText::QuoteName(options.Cache));
      return cached;
    }
  }
  vtkSmartPointer<vtkDataObject> apertures = CastApertures(options, input, messages, error);
  if (apertures && !options.Cache.empty())
  {
    if (!ApertureRender::WriteCache(options.Cache, apertures, fingerprint, messages, error))
    {
      return nullptr;
    }
    Say("apertures: cached in " + vtkApertureText::QuoteName(options.Cache));
  }
  return apertures;
}

// The view: its description, the data, the picture, the window; the exit status.
int Show(const ApertureRender::Options& options, const ApertureRender::Input& input,
  vtkDataObject* apertures, ApertureRender::MessageCapture& messages)
{
  std::string error;
  ApertureRender::View view(options, input, apertures);
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
    // What the mappers fell back on (a mode without its arrays), once each.
    for (const std::string& warning : messages.Warnings())
    {
      Say("note: " + vtkApertureText::Line(warning));
    }
    Say("wrote " + vtksys::SystemTools::CollapseFullPath(options.Output));
  }
  if (options.Interactive)
  {
    view.Interact();
  }
  return 0;
}

int Run(int argc, char* argv[], ApertureRender::MessageCapture& messages)
{
  ApertureRender::Options options;
  ApertureRender::Input input;
  int code = ReadCommandLine(argc, argv, options);
  if (code < 0)
  {
    code = ReadInput(options, messages, input);
  }
  if (code >= 0)
  {
    return code;
  }
  if (input.Volume)
  {
    return ApertureRender::ShowVolume(options, input, messages);
  }
  std::string error;
  vtkSmartPointer<vtkDataObject> apertures = Apertures(options, input, messages, error);
  return apertures ? Show(options, input, apertures, messages) : Fail(error, 1);
}
}

int main(int argc, char* argv[])
{
  int code = 1;
  {
    ApertureRender::MessageCapture messages;
    Messages = &messages;
    std::signal(SIGABRT, OnAbort);
    code = Run(argc, argv, messages);
    // Aborts after this (a leak checker's at exit) find no messages to quote.
    std::signal(SIGABRT, SIG_DFL);
    Messages = nullptr;
  }
  return code;
}
