#pragma once
/// @file MATPicture.h
/// @brief Renders a boundary and its MAT (coloured by Radius) off-screen into a PNG.

#include <string>

class vtkPolyData;
class vtkUnstructuredGrid;

/// Draws the exact boundary (each Bézier cell sampled densely) in dark grey, the MAT
/// polylines coloured by `Radius` with a colour bar, and the graph's nodes as points.
/// Returns false (with a message in `error`) when rendering is not possible.
bool writeMATPicture(vtkUnstructuredGrid* boundary, vtkPolyData* mat, const std::string& png,
  const std::string& title, std::string& error);

/// Draws a solid (its exact faces sampled, translucent), the medial sheets coloured by
/// `Radius`, and the seams, skeletal edges and junctions in dark lines and points, seen
/// obliquely.
bool writeSolidMATPicture(vtkUnstructuredGrid* solid, vtkPolyData* mat, const std::string& png,
  const std::string& title, std::string& error);
