#ifndef NURBSJson_h
#define NURBSJson_h
/**
 * @file NURBSJson.h
 * @brief ExactMAT's JSON format for NURBS boundaries (format "exactmat-nurbs", version 1).
 *
 * ```json
 * { "format": "exactmat-nurbs", "version": 1,
 *   "curves":   [ { "id": 0, "degree": 2, "knots": [0,0,0,1,1,1],
 *                   "points": [[0,0],[1,1],[2,0]], "weights": [1,0.7,1] } ],
 *   "surfaces": [ { "id": 0, "degree": [1,1], "knots": [[0,0,1,1],[0,0,1,1]],
 *                   "size": [2,2], "points": [[0,0,0],[0,1,0],[1,0,0],[1,1,0]] } ] }
 * ```
 * Points are [x, y] or [x, y, z]; surface points are listed with v fastest (index
 * i·size[1] + j). "weights" and "id" are optional (1 and the array index). A file holds
 * curves (a 2D domain) or surfaces (a solid). Loops are found from the geometry.
 */

#include "shapes/Catalogue.h"

#include <string>

namespace exactmat
{
/// Parses the JSON text; throws InputError naming the entry and field that is wrong.
Shape parseNURBSJson(const std::string& text, const std::string& source);
/// Writes the shape as JSON with every number printed exactly (17 significant digits).
std::string writeNURBSJson(const Shape& shape, const std::vector<int>& ids);
} // namespace exactmat

#endif
