#include "compare/Scene_view.h"

#include "compare/Decimal_text.h"
#include "compare/Display_mesh.h"
#include "float/Double_kernel.h"
#include "geometry/Rotation_matrix.h"
#include "model/Model_builder.h"
#include "model/Motion_path.h"
#include "scene/Pose_motion.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

namespace clash4d {
namespace {

using json = nlohmann::ordered_json;
using P3 = std::array<double, 3>;

const char* const palette[] = {"#4e79a7", "#f28e2b", "#59a14f", "#b07aa1", "#76b7b2",
                               "#edc948", "#9c755f", "#ff9da7", "#e15759", "#bab0ac"};
// Subjects' points, apart from the objects' colours.
const char* const subject_palette[] = {"#d62728", "#17becf", "#8c564b", "#e377c2", "#1f77b4", "#bcbd22", "#7f7f7f"};
const char* const exact_witness_colour = "#111111";
const char* const exact_contact_colour = "#ffb000";

// Where the shape is at time t: R(q) p + c.
struct Placement {
  double t;
  P3 c;
  std::array<double, 4> q;   // w x y z, not normalised (R divides by |q|^2)
};

struct View_object {
  std::string name, colour;
  Csg_model<double> csg;
  std::vector<Placement> keys;   // the page interpolates c and q linearly between keys
};

double to_double(const Rational& r) { return round_to_nearest(r); }

// Rotating motions: the poses themselves, since the scene format's law
// (q(t), c(t) linear, R(q) / |q|^2) is what the page evaluates, exactly the
// law and simpler than sampling. Translations: D(t) at tL, every breakpoint
// inside and tH (linear between, so no other key is needed).
std::vector<Placement> placements_of(const Scene_object& o, const Rational& t_lo, const Rational& t_hi)
{
  std::vector<Placement> keys;
  if (o.motion.rotates()) {
    for (const Pose& p : o.motion.poses)
      keys.push_back({to_double(p.t), {to_double(p.translate[0]), to_double(p.translate[1]), to_double(p.translate[2])},
                      {to_double(p.rotate[0]), to_double(p.rotate[1]), to_double(p.rotate[2]), to_double(p.rotate[3])}});
    return keys;
  }
  Double_kernel k;
  Motion_path<double> m = Motion_path<double>::build(k, o.motion);
  double lo = to_double(t_lo), hi = to_double(t_hi);
  std::vector<double> ts{lo};
  for (double t : m.times)
    if (lo < t && t < hi) ts.push_back(t);
  if (hi > lo) ts.push_back(hi);
  for (double t : ts) keys.push_back({t, m.displacement(t), {1, 0, 0, 0}});
  return keys;
}

P3 placed(const Placement& k, const P3& p)
{
  auto r = rotation_matrix(k.q[0], k.q[1], k.q[2], k.q[3]);   // the scene format's R(q), here in doubles (display)
  P3 out;
  for (int i = 0; i < 3; ++i) out[i] = r[i][0] * p[0] + r[i][1] * p[1] + r[i][2] * p[2] + k.c[i];
  return out;
}

// ---------------------------------------------------------------- marks and times

std::optional<P3> point_of(const std::optional<Located>& l, double& t)
{
  if (!l || !l->point) return std::nullopt;
  P3 p;
  for (int i = 0; i < 3; ++i) {
    std::optional<double> d = decimal_value((*l->point)[i]);
    if (!d) return std::nullopt;
    p[i] = *d;
  }
  std::optional<double> time = decimal_value((*l->point)[3]);
  if (!time) return std::nullopt;
  t = *time;
  return p;
}

void add_mark(json& marks, const std::string& label, const std::string& colour, const std::optional<Located>& l)
{
  double t = 0;
  std::optional<P3> p = point_of(l, t);
  if (p) marks.push_back({{"label", label}, {"colour", colour}, {"point", *p}, {"t", t}});
}

void add_time(json& times, const std::string& label, const std::string& text)
{
  if (std::optional<double> t = decimal_value(text)) times.push_back({{"label", label}, {"t", *t}, {"exact", text}});
}

// The exact witness and first contact (regularised, else closed), then each
// other subject's, in its colour.
void marks_and_times(const Comparison& c, json& marks, json& times)
{
  const Subject_row* ref = c.reference();
  const Subject_row* closed = c.reference_in("closed");
  if (ref && ref->witness && ref->witness->point) add_time(times, "witness time", (*ref->witness->point)[3]);
  if (ref) add_mark(marks, "exact witness", exact_witness_colour, ref->witness);
  const Subject_row* contact = ref && ref->earliest ? ref : closed && closed->earliest ? closed : nullptr;
  if (contact) {
    add_time(times, "exact t*", contact->earliest->t);
    add_mark(marks, contact == ref ? "exact contact (t*)" : "exact contact, closed (t*)", exact_contact_colour,
             contact->earliest);
  }
  std::size_t k = 0;
  for (const Subject_row& s : c.subjects) {
    if (s.reference) continue;
    std::string colour = subject_palette[k++ % std::size(subject_palette)];
    if (s.earliest) add_time(times, s.subject + " t*", s.earliest->t);
    add_mark(marks, s.subject + " witness", colour, s.witness);
    add_mark(marks, s.subject + " contact", colour, s.earliest);
  }
}

// ---------------------------------------------------------------- box and meshes

// The bounded objects at every key and the marked points, enlarged by a
// quarter of the largest extent: unbounded cells are cut by it.
std::pair<P3, P3> drawing_box(const std::vector<View_object>& objects, const json& marks)
{
  P3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  auto take = [&](const P3& p) {
    for (int a = 0; a < 3; ++a) { lo[a] = std::min(lo[a], p[a]); hi[a] = std::max(hi[a], p[a]); }
  };
  for (const View_object& o : objects) {
    Box<double, 3> b = node_box(o.csg, 0);
    if (b.empty || !b.bounded()) continue;
    for (const Placement& k : o.keys)
      for (int corner = 0; corner < 8; ++corner)
        take(placed(k, {corner & 1 ? b.hi[0] : b.lo[0], corner & 2 ? b.hi[1] : b.lo[1], corner & 4 ? b.hi[2] : b.lo[2]}));
  }
  for (const json& m : marks) take(m["point"].get<P3>());
  if (!(lo[0] <= hi[0])) { lo = {-1, -1, -1}; hi = {1, 1, 1}; }
  double size = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  double pad = size > 0 ? 0.25 * size : std::max(1.0, std::abs(lo[0]) + std::abs(lo[1]) + std::abs(lo[2]));
  for (int a = 0; a < 3; ++a) { lo[a] -= pad; hi[a] += pad; }
  return {lo, hi};
}

json object_json(const View_object& o, const P3& lo, const P3& hi)
{
  Display_mesh mesh = display_mesh(o.csg, lo, hi);
  json vertices = json::array(), triangles = json::array(), keys = json::array();
  for (const auto& v : mesh.vertices)
    for (double x : v) vertices.push_back(x);
  for (const auto& t : mesh.triangles)
    for (int i : t) triangles.push_back(i);
  for (const Placement& k : o.keys) keys.push_back({{"t", k.t}, {"c", k.c}, {"q", k.q}});
  return {{"name", o.name}, {"colour", o.colour}, {"vertices", vertices}, {"triangles", triangles},
          {"keys", keys}, {"clipped", mesh.clipped}, {"truncated", mesh.truncated}};
}

std::vector<View_object> view_objects(const Report_case& rc, const std::vector<std::size_t>& drawn, json& notes)
{
  std::vector<View_object> out;
  Double_kernel k;
  for (std::size_t n = 0; n < drawn.size(); ++n) {
    const Scene_object& o = rc.scene.objects[drawn[n]];
    try {
      // A rotating object's shape as written: the poses place it.
      const Solid& shape = o.motion.rotates() ? written_shape(o) : o.shape;
      Model_builder<Double_kernel> builder(k);
      out.push_back({o.name, object_colour(n), builder.build(shape), placements_of(o, rc.scene.t_lo, rc.scene.t_hi)});
    } catch (const std::exception& e) {
      notes.push_back("cannot draw " + o.name + ": " + e.what());
    }
  }
  return out;
}

std::string number(double x)
{
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

std::string legend_html(const json& data)
{
  std::string out = "<div class=\"legend\">";
  for (const json& o : data["objects"])
    out += "<span class=\"item\"><span class=\"swatch\" style=\"background:" + o["colour"].get<std::string>() +
           "\"></span>" + escape_markup(o["name"].get<std::string>()) + (o["clipped"].get<bool>() ? " (cut by the drawing box)" : "") +
           "</span>";
  for (const json& m : data["marks"])
    out += "<span class=\"item\"><span class=\"dot\" style=\"background:" + m["colour"].get<std::string>() +
           "\"></span>" + escape_markup(m["label"].get<std::string>()) + "</span>";
  return out + "</div>\n";
}

} // namespace

std::string object_colour(std::size_t k) { return palette[k % std::size(palette)]; }

json scene_view_data(const Report_case& rc, const std::vector<std::size_t>& drawn)
{
  json notes = json::array(), marks = json::array(), times = json::array(), objects = json::array();
  marks_and_times(rc.comparison, marks, times);
  std::vector<View_object> view = view_objects(rc, drawn, notes);
  auto [lo, hi] = drawing_box(view, marks);
  bool clipped = false;
  for (const View_object& o : view) {
    objects.push_back(object_json(o, lo, hi));
    clipped = clipped || objects.back()["clipped"].get<bool>();
    if (objects.back()["truncated"].get<bool>()) notes.push_back(o.name + ": only the first cells of its DNF are drawn");
  }
  if (clipped) notes.push_back("Unbounded solids are cut by the drawing box (the bounded objects over the span and the marked points, enlarged by a quarter)");
  // Where exact says no collision, the page shows how far apart the objects
  // are at the chosen time (doubles, on the drawn triangles).
  const Subject_row* ref = rc.comparison.reference();
  bool gap = ref && ref->collide == false && view.size() >= 2;
  return {{"t", {to_double(rc.scene.t_lo), to_double(rc.scene.t_hi)}}, {"box", {lo, hi}}, {"objects", objects},
          {"marks", marks}, {"times", times}, {"notes", notes}, {"gap", gap}};
}

std::string scene_view_html(const Report_case& rc, std::size_t index, const std::vector<std::size_t>& drawn)
{
  json data = scene_view_data(rc, drawn);
  std::string text = data.dump(-1, ' ', false, json::error_handler_t::replace), safe;
  // Inside <script>, "</script" or "<!--" would end or confuse the element:
  // <, > and & (only ever inside JSON strings) as JSON escapes.
  for (char ch : text) safe += ch == '<' ? "\\u003c" : ch == '>' ? "\\u003e" : ch == '&' ? "\\u0026" : std::string(1, ch);
  std::string out = "<div class=\"view3d\" id=\"view3d-" + std::to_string(index) + "\">\n<div class=\"view-row\">" +
                    "<canvas class=\"view-canvas\" width=\"560\" height=\"420\"></canvas>\n<div class=\"view-side\">" +
                    legend_html(data) + "<div class=\"view-controls\"><label>t <input type=\"range\" class=\"view-time\" min=\"0\" max=\"1000\" value=\"0\"></label> " +
                    "<span class=\"view-t mono\"></span><br>";
  for (const json& t : data["times"])
    out += "<button type=\"button\" data-t=\"" + number(t["t"].get<double>()) + "\" title=\"t = " +
           escape_markup(t["exact"].get<std::string>()) + "\">" + escape_markup(t["label"].get<std::string>()) + "</button> ";
  out += "<button type=\"button\" class=\"view-fit\">fit view</button></div>\n<p class=\"view-note\">Drag to turn, wheel to "
         "zoom, \"fit view\" to frame the objects where they are. Drawn in doubles, for display only.";
  for (const json& n : data["notes"]) out += " " + escape_markup(n.get<std::string>()) + ".";
  out += "</p><p class=\"view-gap\"></p><p class=\"view-msg\"></p></div></div>\n<script type=\"application/json\" class=\"view-data\">" + safe +
         "</script>\n</div>\n";
  return out;
}

} // namespace clash4d

namespace clash4d {

// The page's side: each .view3d's data drawn with three.js (r111, the global
// THREE), objects placed at the chosen time by the same law as the scene
// format's (c and q linear between keys, R(q) / |q|^2; at rest outside).
// With ?shot=N the N-th view is moved to the top of the page (?shot=1: the
// screenshot test).
const char* scene_view_script()
{
  return R"JS(
(function () {
  function rotation(q) {
    var w = q[0], x = q[1], y = q[2], z = q[3], n = w * w + x * x + y * y + z * z;
    return [[(w*w + x*x - y*y - z*z) / n, 2 * (x*y - w*z) / n, 2 * (x*z + w*y) / n],
            [2 * (x*y + w*z) / n, (w*w - x*x + y*y - z*z) / n, 2 * (y*z - w*x) / n],
            [2 * (x*z - w*y) / n, 2 * (y*z + w*x) / n, (w*w - x*x - y*y + z*z) / n]];
  }
  function placement(keys, t) {
    if (t <= keys[0].t) return keys[0];
    var last = keys[keys.length - 1];
    if (t >= last.t) return last;
    var i = 0;
    while (t > keys[i + 1].t) ++i;
    var a = keys[i], b = keys[i + 1], s = (t - a.t) / (b.t - a.t), c = [], q = [];
    for (var k = 0; k < 3; ++k) c.push((1 - s) * a.c[k] + s * b.c[k]);
    for (k = 0; k < 4; ++k) q.push((1 - s) * a.q[k] + s * b.q[k]);
    return {c: c, q: q};
  }
  function geometry(o) {
    var positions = new Float32Array(o.triangles.length * 3);
    for (var i = 0; i < o.triangles.length; ++i)
      for (var k = 0; k < 3; ++k) positions[3 * i + k] = o.vertices[3 * o.triangles[i] + k];
    var g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    g.computeVertexNormals();
    return g;
  }
  // The scene of a view: lights on the camera, the drawing box, the solids
  // (placed by their matrices) and the marks.
  function build(data, canvas) {
    var v = {scene: new THREE.Scene(), data: data};
    v.scene.background = new THREE.Color(0xffffff);
    var lo = data.box[0], hi = data.box[1];
    v.box = new THREE.Box3(new THREE.Vector3(lo[0], lo[1], lo[2]), new THREE.Vector3(hi[0], hi[1], hi[2]));
    v.size = Math.max(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    v.centre = v.box.getCenter(new THREE.Vector3());
    v.camera = new THREE.PerspectiveCamera(40, canvas.width / canvas.height, v.size / 1000, v.size * 100);
    v.camera.up.set(0, 0, 1);
    v.camera.add(new THREE.DirectionalLight(0xffffff, 0.55));
    v.scene.add(v.camera, new THREE.AmbientLight(0xffffff, 0.55), new THREE.Box3Helper(v.box, 0xdddddd));
    v.meshes = data.objects.map(function (o) {
      var g = geometry(o);
      // An unbounded (cut) solid shows its outside only, fainter: the camera
      // is often inside it, and then sees through it.
      var m = new THREE.Mesh(g, new THREE.MeshLambertMaterial({color: o.colour, transparent: true,
        side: o.clipped ? THREE.FrontSide : THREE.DoubleSide, opacity: o.clipped ? 0.45 : 0.8}));
      m.add(new THREE.LineSegments(new THREE.EdgesGeometry(g, 20), new THREE.LineBasicMaterial({color: 0x333333})));
      m.matrixAutoUpdate = false;
      v.scene.add(m);
      return m;
    });
    v.spheres = data.marks.map(function (k, i) {
      var s = new THREE.Mesh(new THREE.SphereGeometry(1, 16, 12), new THREE.MeshBasicMaterial({color: k.colour, depthTest: false, transparent: true}));
      // Seen through the solids (the points are what the case is about):
      // drawn after them (transparent pass, high order), the exact ones
      // (listed first) over the subjects'.
      s.renderOrder = 1000 - i;
      s.position.set(k.point[0], k.point[1], k.point[2]);
      v.scene.add(s);
      return s;
    });
    v.orbit = {theta: -0.9, phi: 1.05, radius: v.size * 1.5};
    return v;
  }
  function render(v) {
    var r = v.orbit.radius, p = v.orbit.phi, th = v.orbit.theta, c = v.centre;
    v.camera.position.set(c.x + r * Math.sin(p) * Math.cos(th), c.y + r * Math.sin(p) * Math.sin(th), c.z + r * Math.cos(p));
    v.camera.lookAt(c);
    v.renderer.render(v.scene, v.camera);
  }
  // The camera on the bounded objects where they are now and the marks (the
  // drawing box when there are none); the marks sized to match.
  function fit(v) {
    v.scene.updateMatrixWorld(true);
    var b = new THREE.Box3();
    v.meshes.forEach(function (m, i) { if (!v.data.objects[i].clipped) b.expandByObject(m); });
    v.spheres.forEach(function (s) { b.expandByPoint(s.position); });
    if (b.isEmpty()) b.copy(v.box);
    var extent = b.getSize(new THREE.Vector3()), reach = Math.max(extent.x, extent.y, extent.z, v.size * 1e-6);
    b.getCenter(v.centre);
    v.orbit.radius = reach * 3;
    v.spheres.forEach(function (s) { s.scale.setScalar(reach / 30); });
    render(v);
  }
  // Ericson's closest points of two segments: their distance.
  function segmentDistance(p1, q1, p2, q2) {
    var d1 = q1.clone().sub(p1), d2 = q2.clone().sub(p2), r = p1.clone().sub(p2);
    var a = d1.dot(d1), e = d2.dot(d2), f = d2.dot(r), s = 0, t = 0;
    function clamp(x) { return Math.min(1, Math.max(0, x)); }
    if (a > 0 && e > 0) {
      var b = d1.dot(d2), c = d1.dot(r), denom = a * e - b * b;
      s = denom > 0 ? clamp((b * f - c * e) / denom) : 0;
      t = (b * s + f) / e;
      if (t < 0) { t = 0; s = clamp(-c / a); } else if (t > 1) { t = 1; s = clamp((b - c) / a); }
    } else if (a > 0) s = clamp(-d1.dot(r) / a);
    else if (e > 0) t = clamp(f / e);
    return p1.clone().addScaledVector(d1, s).distanceTo(p2.clone().addScaledVector(d2, t));
  }
  function placedTriangles(mesh) {
    var pos = mesh.geometry.attributes.position, out = [];
    function at(k) { return new THREE.Vector3().fromBufferAttribute(pos, k).applyMatrix4(mesh.matrix); }
    for (var k = 0; k < pos.count; k += 3) out.push(new THREE.Triangle(at(k), at(k + 1), at(k + 2)));
    return out;
  }
  // The distance of two closed surfaces that do not overlap: the least over
  // vertex-triangle and edge-edge pairs.
  function surfaceDistance(A, B) {
    var best = Infinity, q = new THREE.Vector3();
    A.forEach(function (ta) {
      B.forEach(function (tb) {
        [ta.a, ta.b, ta.c].forEach(function (p) { best = Math.min(best, p.distanceTo(tb.closestPointToPoint(p, q))); });
        [tb.a, tb.b, tb.c].forEach(function (p) { best = Math.min(best, p.distanceTo(ta.closestPointToPoint(p, q))); });
        [[ta.a, ta.b], [ta.b, ta.c], [ta.c, ta.a]].forEach(function (x) {
          [[tb.a, tb.b], [tb.b, tb.c], [tb.c, tb.a]].forEach(function (y) { best = Math.min(best, segmentDistance(x[0], x[1], y[0], y[1])); });
        });
      });
    });
    return best;
  }
  // The closest pair of objects now, when exact says they never collide
  // (small meshes only: every pair of triangles is tried).
  function showGap(v, t) {
    var out = v.root.querySelector('.view-gap');
    if (!v.data.gap) return;
    var tris = v.meshes.map(placedTriangles), best = null;
    for (var i = 0; i < tris.length; ++i)
      for (var j = i + 1; j < tris.length; ++j) {
        if (tris[i].length * tris[j].length > 40000) { out.textContent = 'Gap not computed: the meshes are too large.'; return; }
        var d = surfaceDistance(tris[i], tris[j]);
        if (!best || d < best.d) best = {d: d, a: v.data.objects[i].name, b: v.data.objects[j].name};
      }
    out.textContent = 'At t \u2248 ' + Number(t.toPrecision(6)) + ' the closest objects, ' + best.a + ' and ' + best.b +
      ', are \u2248 ' + Number(best.d.toPrecision(3)) + ' apart (doubles, drawn triangles: 0 means touching up to rounding).';
  }
  function setTime(v, t) {
    var t0 = v.data.t[0], t1 = v.data.t[1];
    v.data.objects.forEach(function (o, i) {
      var p = placement(o.keys, t), r = rotation(p.q);
      v.meshes[i].matrix.set(r[0][0], r[0][1], r[0][2], p.c[0], r[1][0], r[1][1], r[1][2], p.c[1],
                             r[2][0], r[2][1], r[2][2], p.c[2], 0, 0, 0, 1);
      v.meshes[i].matrixWorldNeedsUpdate = true;
    });
    v.label.textContent = 't \u2248 ' + Number(t.toPrecision(6));
    if (t1 > t0) v.slider.value = Math.round((t - t0) / (t1 - t0) * 1000);
    showGap(v, t);
    render(v);
  }
  // The slider, the time buttons, "fit view"; drag turns about the centre, the wheel zooms.
  function controls(v, root, canvas) {
    var t0 = v.data.t[0], t1 = v.data.t[1], drag = null;
    v.slider.addEventListener('input', function () { setTime(v, t0 + (t1 - t0) * v.slider.value / 1000); });
    root.querySelector('.view-fit').addEventListener('click', function () { fit(v); });
    root.querySelectorAll('button[data-t]').forEach(function (b) {
      b.addEventListener('click', function () { setTime(v, Number(b.getAttribute('data-t'))); });
    });
    canvas.addEventListener('mousedown', function (e) { drag = [e.clientX, e.clientY]; e.preventDefault(); });
    window.addEventListener('mouseup', function () { drag = null; });
    window.addEventListener('mousemove', function (e) {
      if (!drag) return;
      v.orbit.theta -= (e.clientX - drag[0]) * 0.01;
      v.orbit.phi = Math.min(3.1, Math.max(0.04, v.orbit.phi - (e.clientY - drag[1]) * 0.01));
      drag = [e.clientX, e.clientY];
      render(v);
    });
    canvas.addEventListener('wheel', function (e) {
      v.orbit.radius *= Math.exp(e.deltaY * 0.001);
      e.preventDefault();
      render(v);
    }, {passive: false});
  }
  function view(root) {
    var data = JSON.parse(root.querySelector('.view-data').textContent);
    var msg = root.querySelector('.view-msg'), canvas = root.querySelector('canvas'), renderer;
    if (typeof THREE === 'undefined') { msg.textContent = 'The 3D view needs three.js (three.min.js beside this page).'; return; }
    try { renderer = new THREE.WebGLRenderer({canvas: canvas, antialias: true, preserveDrawingBuffer: true}); }
    catch (e) { msg.textContent = 'The 3D view needs WebGL: ' + e; return; }
    var v = build(data, canvas);
    v.renderer = renderer;
    v.root = root;
    v.label = root.querySelector('.view-t');
    v.slider = root.querySelector('.view-time');
    controls(v, root, canvas);
    // At the exact t* when there is one, else at the first time offered.
    var start = data.times.length ? data.times[0].t : data.t[0];
    data.times.forEach(function (x) { if (x.label === 'exact t*') start = x.t; });
    setTime(v, start);
    fit(v);
  }
  var views = document.querySelectorAll('.view3d');
  var shot = /[?&]shot=(\d+)/.exec(location.search);
  if (shot && views[shot[1] - 1]) document.body.insertBefore(views[shot[1] - 1], document.body.firstChild);
  views.forEach(view);
})();
)JS";
}

} // namespace clash4d
