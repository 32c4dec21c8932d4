/* Copyright (c) 2026 The Flow_aligned_surfaces developers.
 * SPDX-License-Identifier: GPL-3.0-or-later
 *
 * Preloaded into ParaView's processes (LD_PRELOAD), turns off expat's "reparse deferral" in
 * every parser they create.  Debian's security updates of expat (bookworm's 2.5.0-1+deb12u2 and
 * later, the fix of CVE-2023-52425) defer the parsing of large tokens; ParaView 5.11's bundled
 * VTK, built before, then fails on every VTK XML stream whose data is appended ("not
 * well-formed (invalid token)"): appended .vtu/.vti/.vtp files, and the pieces that
 * RedistributeDataSet ships between MPI ranks, which are silently lost.  Debian's own VTK 9.1
 * was patched to make the same call on its parsers.
 *
 * Each of expat's three parser constructors is wrapped: the real one (the next definition of
 * the symbol, normally libexpat's) creates the parser, then XML_SetReparseDeferralEnabled(parser,
 * XML_FALSE).  Where expat has no such function (before the fix) the parsers are left as they
 * are, which is what they were.  Only these three symbols are defined; everything else of expat
 * is untouched.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <expat.h>
#include <stddef.h>

typedef XML_Bool (*Set_reparse_deferral)(XML_Parser, XML_Bool);

static XML_Parser deferral_off(XML_Parser parser)
{
  static Set_reparse_deferral set = NULL;
  static int looked_up = 0;
  if (!looked_up) {
    set = (Set_reparse_deferral)dlsym(RTLD_DEFAULT, "XML_SetReparseDeferralEnabled");
    looked_up = 1;
  }
  if (parser != NULL && set != NULL)
    set(parser, XML_FALSE);
  return parser;
}

XML_Parser XMLCALL XML_ParserCreate(const XML_Char* encoding)
{
  typedef XML_Parser (*Create)(const XML_Char*);
  static Create create = NULL;
  if (create == NULL)
    create = (Create)dlsym(RTLD_NEXT, "XML_ParserCreate");
  return create == NULL ? NULL : deferral_off(create(encoding));
}

XML_Parser XMLCALL XML_ParserCreateNS(const XML_Char* encoding, XML_Char separator)
{
  typedef XML_Parser (*Create)(const XML_Char*, XML_Char);
  static Create create = NULL;
  if (create == NULL)
    create = (Create)dlsym(RTLD_NEXT, "XML_ParserCreateNS");
  return create == NULL ? NULL : deferral_off(create(encoding, separator));
}

XML_Parser XMLCALL XML_ParserCreate_MM(const XML_Char* encoding, const XML_Memory_Handling_Suite* memory,
                                       const XML_Char* separator)
{
  typedef XML_Parser (*Create)(const XML_Char*, const XML_Memory_Handling_Suite*, const XML_Char*);
  static Create create = NULL;
  if (create == NULL)
    create = (Create)dlsym(RTLD_NEXT, "XML_ParserCreate_MM");
  return create == NULL ? NULL : deferral_off(create(encoding, memory, separator));
}
