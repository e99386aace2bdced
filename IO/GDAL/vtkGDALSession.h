/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkGDALSession.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkGDALSession
 * @brief   GDAL registered, and its messages kept rather than printed, while it lives (private)
 *
 * GDAL prints its errors on stderr by default; the readers and writers report them through
 * vtkErrorMacro instead. A session registers GDAL's drivers once per process and installs a quiet
 * error handler on the calling thread until it is destroyed; LastError() is GDAL's last message.
 */

#ifndef vtkGDALSession_h
#define vtkGDALSession_h

#include "vtkApertureLightingIOGDALModule.h" // For export macro

#include <string>

class VTKAPERTURELIGHTINGIOGDAL_EXPORT vtkGDALSession
{
public:
  vtkGDALSession();
  ~vtkGDALSession();
  vtkGDALSession(const vtkGDALSession&) = delete;
  vtkGDALSession& operator=(const vtkGDALSession&) = delete;

  /// GDAL's last error message since the session began, or "unknown error".
  std::string LastError() const;
};

#endif
// VTK-HeaderTest-Exclude: vtkGDALSession.h
