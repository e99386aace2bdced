/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderCache.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "ApertureRenderCache.h"

#include "ApertureRenderInput.h"
#include "ApertureRenderMessages.h"
#include "ApertureRenderOptions.h"
#include "ApertureRenderXMLBlocks.h"

#include "vtkApertureText.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkStringArray.h"
#include "vtkXMLImageDataReader.h"
#include "vtkXMLImageDataWriter.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"
#include "vtksys/SystemTools.hxx"

#include <cstdint>
#include <cstdio>

namespace ApertureRender
{
namespace
{
const char* const FingerprintName = "ApertureRenderFingerprint";

// 64-bit FNV-1a.
class Hash
{
public:
  void Add(const void* data, size_t size)
  {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < size; ++i)
    {
      this->Value = (this->Value ^ bytes[i]) * 1099511628211ull;
    }
  }
  void Add(double value) { this->Add(&value, sizeof(value)); }
  void Add(const std::string& text) { this->Add(text.data(), text.size()); }
  void Add(vtkDataArray* array)
  {
    for (vtkIdType i = 0; array && i < array->GetNumberOfValues(); ++i)
    {
      this->Add(array->GetVariantValue(i).ToDouble());
    }
  }
  void Add(vtkCellArray* cells)
  {
    if (cells)
    {
      this->Add(cells->GetOffsetsArray());
      this->Add(cells->GetConnectivityArray());
    }
  }
  std::string Hex() const
  {
    char text[17];
    std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(this->Value));
    return text;
  }

private:
  uint64_t Value = 14695981039346656037ull;
};
}

std::string Fingerprint(const Input& input, const Options& options)
{
  Hash hash;
  hash.Add(std::string("aperture-render " APERTURE_RENDER_VERSION));
  hash.Add(static_cast<double>(options.Rays));
  hash.Add(static_cast<double>(options.RaysGiven ? -1 : options.Sectors));
  hash.Add(WantsHorizons(options) && input.Heights ? 1.0 : 0.0);
  hash.Add(WantsMasks(options) && !input.Heights ? 1.0 : 0.0);
  if (input.Heights)
  {
    int dims[3];
    input.Heights->GetDimensions(dims);
    hash.Add(dims, sizeof(dims));
    hash.Add(input.Heights->GetSpacing(), 3 * sizeof(double));
    hash.Add(input.Heights->GetOrigin(), 3 * sizeof(double));
    hash.Add(options.HeightScale);
    hash.Add(input.Heights->GetPointData()->GetScalars());
  }
  else
  {
    hash.Add(input.Mesh->GetPoints() ? input.Mesh->GetPoints()->GetData() : nullptr);
    hash.Add(input.Mesh->GetPolys());
    hash.Add(input.Mesh->GetStrips());
    hash.Add(input.Mesh->GetPointData()->GetNormals());
    hash.Add(options.Crease);
    hash.Add(input.MaximumEdge);
  }
  return hash.Hex();
}

vtkSmartPointer<vtkDataObject> ReadCache(const std::string& path, const std::string& fingerprint,
  bool heightField, MessageCapture& messages, std::string& note)
{
  note.clear();
  if (!vtksys::SystemTools::FileExists(path, true))
  {
    return nullptr;
  }
  vtkSmartPointer<vtkXMLReader> reader;
  if (heightField)
  {
    reader = vtkSmartPointer<vtkXMLImageDataReader>::New();
  }
  else
  {
    reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  }
  if (!reader->CanReadFile(path.c_str()))
  {
    note = "the cache " + vtkApertureText::QuoteName(path) +
      " is not a VTK XML file of the right type; recomputing";
    return nullptr;
  }
  reader->SetFileName(path.c_str());
  messages.Clear();
  std::string damage;
  if (!CheckCompressedBlocks(reader, path, damage))
  {
    note = "the cache " + damage + "; recomputing";
    return nullptr;
  }
  reader->Update();
  auto* data = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  if (!messages.FirstError().empty() || !data)
  {
    note = "the cache " + vtkApertureText::QuoteName(path) + " cannot be read (" +
      messages.FirstError() + "); recomputing";
    messages.Clear();
    return nullptr;
  }
  auto* stored =
    vtkStringArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(FingerprintName));
  if (!stored || stored->GetNumberOfValues() != 1 || stored->GetValue(0) != fingerprint ||
    !data->GetPointData()->GetArray("BentNormal") ||
    !data->GetPointData()->GetArray("ApertureRadius"))
  {
    note = "the cache " + vtkApertureText::QuoteName(path) +
      " was made for other data or settings; recomputing";
    return nullptr;
  }
  data->GetFieldData()->RemoveArray(FingerprintName);
  vtkSmartPointer<vtkDataObject> result;
  result.TakeReference(data->NewInstance());
  result->ShallowCopy(data);
  return result;
}

bool WriteCache(const std::string& path, vtkDataObject* apertures, const std::string& fingerprint,
  MessageCapture& messages, std::string& error)
{
  vtkSmartPointer<vtkDataObject> copy;
  copy.TakeReference(apertures->NewInstance());
  copy->ShallowCopy(apertures);
  vtkNew<vtkFieldData> fields;
  fields->ShallowCopy(apertures->GetFieldData());
  vtkNew<vtkStringArray> stamp;
  stamp->SetName(FingerprintName);
  stamp->InsertNextValue(fingerprint);
  fields->AddArray(stamp);
  copy->SetFieldData(fields);

  vtkSmartPointer<vtkXMLWriter> writer;
  if (copy->IsA("vtkImageData"))
  {
    writer = vtkSmartPointer<vtkXMLImageDataWriter>::New();
  }
  else
  {
    writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
  }
  writer->SetInputData(copy);
  writer->SetFileName(path.c_str());
  messages.Clear();
  if (!writer->Write() || !messages.FirstError().empty())
  {
    error = "cannot write the cache " + vtkApertureText::QuoteName(path) +
      (messages.FirstError().empty() ? std::string() : ": " + messages.FirstError());
    return false;
  }
  return true;
}
}
