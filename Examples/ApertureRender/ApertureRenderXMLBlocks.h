/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderXMLBlocks.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// VTK 9.1's XML readers trust the header in front of each compressed array (the number of
// blocks, their sizes before and after compression): a damaged one makes vtkXMLDataParser
// allocate and fill what it announces, gigabytes, before the read fails, and a block size of 0
// divides by zero. The headers of a VTI or VTP file are checked here against the file first.

#ifndef ApertureRenderXMLBlocks_h
#define ApertureRenderXMLBlocks_h

#include <string>

class vtkXMLReader;

namespace ApertureRender
{
// True when every compressed array's header in the file `reader` reads fits that file (and for
// files that are not compressed or cannot be parsed: the reader reports those); else false with
// one sentence in `error`. Calls the reader's UpdateInformation().
bool CheckCompressedBlocks(vtkXMLReader* reader, const std::string& name, std::string& error);
}

#endif
