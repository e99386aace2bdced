/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureNIfTIReader.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureNIfTIReader.h"

#include "vtkApertureText.h"
#include "vtkObjectFactory.h"
#include "vtk_zlib.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

vtkStandardNewMacro(vtkApertureNIfTIReader);

namespace
{
// Fixed-size fields of a header held in memory, in the file's byte order.
class Fields
{
public:
  Fields(const unsigned char* bytes, bool swap)
    : Bytes(bytes)
    , Swap(swap)
  {
  }

  template <typename T>
  T Get(int offset) const
  {
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, this->Bytes + offset, sizeof(T));
    if (this->Swap)
    {
      std::reverse(raw, raw + sizeof(T));
    }
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
  }

  // Whether `count` values of type T from `offset` on are all finite.
  template <typename T>
  bool Finite(int offset, int count) const
  {
    for (int i = 0; i < count; ++i)
    {
      if (!std::isfinite(
            static_cast<double>(this->Get<T>(offset + i * static_cast<int>(sizeof(T))))))
      {
        return false;
      }
    }
    return true;
  }

private:
  const unsigned char* Bytes;
  bool Swap;
};

// Where a version keeps its fields (byte offsets).
struct Layout
{
  int Size, Magic, Dim, DataType, BitPix, PixDim, VoxOffset, Slope, Quatern, Srow;
};
constexpr Layout NIfTI1 = { 348, 344, 40, 70, 72, 76, 108, 112, 256, 280 };
constexpr Layout NIfTI2 = { 540, 4, 16, 12, 14, 104, 168, 176, 352, 400 };

// The bits of NIfTI's data types; 0 for one VTK does not read.
int BitsOf(int type)
{
  switch (type)
  {
    case 2:   // unsigned char
    case 256: // signed char
      return 8;
    case 4:   // short
    case 512: // unsigned short
      return 16;
    case 8:   // int
    case 16:  // float
    case 768: // unsigned int
      return 32;
    case 64:   // double
    case 1024: // long long
    case 1280: // unsigned long long
      return 64;
    case 128: // RGB
      return 24;
    case 2304: // RGBA
      return 32;
    default:
      return 0;
  }
}

// What is wrong with a header (empty when nothing is), given the file's size (0 when
// compressed).
template <typename Dim, typename Real, typename Offset>
std::string Problem(const Fields& f, const Layout& at, std::uint64_t fileSize)
{
  const auto axes = static_cast<long long>(f.Get<Dim>(at.Dim));
  if (axes < 1 || axes > 7)
  {
    return "it has " + std::to_string(axes) + " axes (1 to 7 expected)";
  }
  double values = 1.0;
  for (int k = 1; k <= axes; ++k)
  {
    const auto samples =
      static_cast<double>(f.Get<Dim>(at.Dim + k * static_cast<int>(sizeof(Dim))));
    if (samples < 1.0)
    {
      return "an axis has no samples";
    }
    values *= samples;
  }
  const int bits = BitsOf(f.Get<std::int16_t>(at.DataType));
  if (values > 2147483647.0)
  {
    return "it declares more than 2^31 values";
  }
  if (bits == 0 || f.Get<std::int16_t>(at.BitPix) != bits)
  {
    return "its data type is not one VTK reads, or does not match its bits per value";
  }
  const double offset = static_cast<double>(f.Get<Offset>(at.VoxOffset));
  if (!f.template Finite<Real>(at.PixDim, 8) || !f.template Finite<Real>(at.Slope, 2) ||
    !f.template Finite<Real>(at.Quatern, 6) || !f.template Finite<Real>(at.Srow, 12) ||
    !std::isfinite(offset))
  {
    return "a spacing, transform, scaling or data offset is not a finite number";
  }
  if (offset < at.Size || (fileSize > 0 && offset + values * bits / 8.0 > fileSize))
  {
    return "its data does not lie after its header, within the file";
  }
  return std::string();
}

// The file's first bytes (decompressed where it is gzipped): a whole NIfTI-2 header or less.
std::vector<unsigned char> FirstBytes(const std::string& name)
{
  std::vector<unsigned char> bytes(NIfTI2.Size);
  gzFile file = gzopen(name.c_str(), "rb");
  const int read = file ? gzread(file, bytes.data(), static_cast<unsigned>(bytes.size())) : 0;
  if (file)
  {
    gzclose(file);
  }
  bytes.resize(static_cast<size_t>(std::max(read, 0)));
  return bytes;
}
}

//------------------------------------------------------------------------------
vtkApertureNIfTIReader::vtkApertureNIfTIReader() = default;

//------------------------------------------------------------------------------
vtkApertureNIfTIReader::~vtkApertureNIfTIReader() = default;

//------------------------------------------------------------------------------
std::string vtkApertureNIfTIReader::HeaderProblem(const char* fileName)
{
  const std::string name = fileName ? fileName : "";
  const std::vector<unsigned char> bytes = FirstBytes(name);
  std::int32_t size = 0;
  if (bytes.size() >= 4)
  {
    std::memcpy(&size, bytes.data(), 4);
  }
  const auto swapped =
    static_cast<std::int32_t>(__builtin_bswap32(static_cast<std::uint32_t>(size)));
  const bool swap = swapped == NIfTI1.Size || swapped == NIfTI2.Size;
  const int version = (swap ? swapped : size) == NIfTI2.Size ? 2 : 1;
  const Layout& at = version == 2 ? NIfTI2 : NIfTI1;
  std::string why;
  if ((swap ? swapped : size) != at.Size || bytes.size() < static_cast<size_t>(at.Size))
  {
    why = "it does not start with a NIfTI-1 or NIfTI-2 header";
  }
  else if (std::memcmp(&bytes[at.Magic], version == 2 ? "n+2" : "n+1", 4) != 0)
  {
    why = "its header is not that of a single-file volume (n+1 or n+2)";
  }
  else
  {
    const Fields fields(bytes.data(), swap);
    const bool gzipped = vtksys::SystemTools::LowerCase(name).rfind(".gz") + 3 == name.size();
    const std::uint64_t fileSize = gzipped ? 0 : vtksys::SystemTools::FileLength(name);
    why = version == 2 ? Problem<std::int64_t, double, std::int64_t>(fields, at, fileSize)
                       : Problem<std::int16_t, float, float>(fields, at, fileSize);
  }
  return why.empty()
    ? why
    : vtkApertureText::QuoteName(name) + " is not a NIfTI file VTK can read: " + why;
}

//------------------------------------------------------------------------------
int vtkApertureNIfTIReader::CanReadFile(const char* fileName)
{
  return HeaderProblem(fileName).empty() ? this->Superclass::CanReadFile(fileName) : 0;
}

//------------------------------------------------------------------------------
int vtkApertureNIfTIReader::RequestInformation(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const std::string problem = HeaderProblem(this->GetFileName());
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem << ".");
    return 0;
  }
  return this->Superclass::RequestInformation(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
int vtkApertureNIfTIReader::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // ParaView's pipeline asks for the data even after RequestInformation failed (and reported
  // why); vtkNIFTIImageReader would then read the damaged header again.
  if (!HeaderProblem(this->GetFileName()).empty())
  {
    return 0;
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
void vtkApertureNIfTIReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
