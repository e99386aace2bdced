/*=========================================================================

  Program:   ApertureLighting
  Module:    keep-loaded.c

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/* Preloaded by `make sanitize`: libraries stay loaded, because Mesa unloads its driver when a
 * context goes, and LeakSanitizer can then neither name nor suppress what the driver left. */

int dlclose(void* handle)
{
  (void)handle;
  return 0;
}
