/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkGDALSession.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkGDALSession.h"

#include "vtkApertureText.h"

#include <cpl_error.h>
#include <gdal.h>

#include <mutex>

//------------------------------------------------------------------------------
vtkGDALSession::vtkGDALSession()
{
  static std::once_flag registered;
  std::call_once(registered, [] { GDALAllRegister(); });
  CPLPushErrorHandler(CPLQuietErrorHandler);
  CPLErrorReset();
}

//------------------------------------------------------------------------------
vtkGDALSession::~vtkGDALSession()
{
  CPLPopErrorHandler();
}

//------------------------------------------------------------------------------
std::string vtkGDALSession::LastError() const
{
  // GDAL's messages quote the files it reads.
  const char* message = CPLGetLastErrorMsg();
  return message && *message ? vtkApertureText::Line(message, 200) : "unknown error";
}
