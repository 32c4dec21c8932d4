// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The flow-field readers of the package, one header per file format; include this one
// to have them all.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_READ_FLOW_FIELD_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_READ_FLOW_FIELD_H

#include <CGAL/Flow_aligned_surfaces/IO/read_AmiraMesh.h>
#include <CGAL/Flow_aligned_surfaces/IO/read_NRRD.h>
#include <CGAL/Flow_aligned_surfaces/IO/read_VTK_legacy.h>

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_READ_FLOW_FIELD_H
