// The report's 3D view of a scene case: its solids as triangles
// (compare/Display_mesh.h), their motions, the witness and contact points,
// drawn by three.js in the page. Doubles throughout, for drawing only.
#ifndef CLASH4D_COMPARE_SCENE_VIEW_H
#define CLASH4D_COMPARE_SCENE_VIEW_H

#include "compare/Report_writer.h"
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace clash4d {

// The colour of the k-th drawn object (the q-t diagrams' too).
std::string object_colour(std::size_t k);

// The view's data: the drawing box, each drawn object (objects[i] for i in
// drawn, coloured object_colour(k) for the k-th) with its triangles and
// placements, the marked points and the times the buttons go to.
nlohmann::ordered_json scene_view_data(const Report_case& rc, const std::vector<std::size_t>& drawn);

// The view of case `index` as an HTML fragment (canvas, controls, legend,
// the data as JSON); scene_view_script() brings every such fragment of the
// page to life.
std::string scene_view_html(const Report_case& rc, std::size_t index, const std::vector<std::size_t>& drawn);
const char* scene_view_script();

} // namespace clash4d

#endif
