#include "cli/Commands.h"
#include "cli/Campaign_commands.h"
#include "cli/Ccd_command.h"
#include "cli/Rotating_check_command.h"
#include "cli/Stats_json.h"
#include "certify/Certificate_writer.h"
#include "cli/Verify_command.h"
#include "compare/Ccd_comparer.h"
#include "compare/Ccd_query_files.h"
#include "compare/Comparer.h"
#include "compare/Decimal_text.h"
#include "compare/Progress_line.h"
#include "exact/Exact_instantiation.h"
#include "exact/Witness_depth.h"
#include "float/Double_instantiation.h"
#include "rotation/Rotating_check.h"
#include "certify/Turning_certificate.h"
#include "certify/Turning_prover.h"
#include "rotation/Critical_times.h"
#include "rotation/Rotating_extrusion.h"
#include "scene/Files.h"
#include "scene/Input_error.h"
#include "scene/Rotation_refusal.h"
#include "scene/Printable.h"
#include "scene/Grid_scene.h"
#include "run/Work_budget.h"
#include "scene/Scene_reader.h"
#include "scene/Slow_step_note.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <tbb/global_control.h>
#include <unistd.h>
#include <ostream>

namespace clash4d {
namespace {

constexpr int CLASH4D_EXIT_INTERNAL = 4;
using json = nlohmann::ordered_json;

const char* const about =
    "clash4d: exact collision detection by four-dimensional intersection testing\n"
    "(Cameron 1990). Objects are CSG solids of linear half-spaces under piecewise-\n"
    "constant velocities; two objects collide when the regularised intersection\n"
    "of their space-time extrusions is non-empty, so touching is not a collision.\n"
    "Solids: halfspace, block, convex, prism, hull, mesh (a closed OFF, OBJ, STL or\n"
    "PLY file relative to the scene: {\"mesh\": \"parts/gripper.stl\"}, docs/meshes.md),\n"
    "union, intersection, difference, translate, rotate.\n"
    "\nExit status: 0 no collision / valid, 1 collision, 2 invalid input or usage,\n"
    "3 a resource limit was reached, 4 internal error.";

// The folders besides each scene's own that its mesh files may be in
// (--allow-mesh-path, docs/meshes.md), as the command line gave them.
std::vector<std::string> allowed_mesh_folders;

// Reads a scene, or prints why not; returns the exit status (0 when read).
int load(const std::string& file, Scene& scene, std::ostream& err)
{
  try {
    scene = read_scene_file(file, allowed_mesh_folders);
    // Reading may take long (a mesh's convex decomposition is one CGAL call
    // that cannot be cut short): past the budget, no answer (issue 59 item 6).
    Work_budget::check();
    return 0;
  } catch (const Input_error& e) {
    err << e.format(file) << "\n";
    return e.exit_code();
  }
}

// Runs an instantiation, turning its failures into messages and statuses.
template <class Run>
int guarded(const std::string& file, std::ostream& err, Run run)
{
  try {
    return run();
  } catch (const Input_error& e) {
    err << e.format(file) << "\n";
    return e.exit_code();
  } catch (const std::range_error& e) {
    err << file << ": " << e.what() << " (the double instantiation cannot read this scene)\n";
    return CLASH4D_EXIT_INVALID;
  } catch (const std::bad_alloc&) {
    err << file << ": out of memory\n";
    return CLASH4D_EXIT_LIMIT;
  } catch (const std::logic_error& e) {
    err << file << ": " << e.what() << "\n";
    return CLASH4D_EXIT_INTERNAL;
  } catch (const std::runtime_error& e) {   // none is expected here: a message, never a crash
    err << file << ": " << e.what() << "\n";
    return CLASH4D_EXIT_INTERNAL;
  }
}

// The objects moving by poses (spec: Motion with rotation (poses)), and
// whether each rotates: which commands decide the scene depends on it.
std::string pose_note(const Scene& scene)
{
  std::string note;
  for (const Scene_object& o : scene.objects)
    if (!o.motion.poses.empty())
      note += std::string(note.empty() ? " (pose motions: " : ", ") + "\"" + o.name + "\" " +
              (o.motion.rotates() ? "rotates" : "translates only");
  return note.empty() ? note : note + ")";
}

int validate(const std::vector<std::string>& files, std::ostream& out, std::ostream& err)
{
  int status = 0;
  for (const auto& f : files) {
    Scene scene;
    int s = load(f, scene, err);
    if (s == 0) out << f << ": valid" << pose_note(scene) << "\n";
    else if (status == 0 || s == CLASH4D_EXIT_INVALID) status = s;
  }
  return status;
}

void print_extrusion_text(const json& report, std::ostream& out)
{
  out << "number: " << report["number"].get<std::string>() << "\n";
  std::function<void(const json&, int)> tree = [&](const json& node, int depth) {
    std::string pad(2 * depth, ' ');
    if (node.contains("primitive")) {
      out << pad << "primitive " << node["primitive"].get<std::string>() << ": intersection of\n";
      for (const auto& h : node["halfspaces"]) out << pad << "  " << h["text"].get<std::string>() << "\n";
    } else if (node.contains("time")) {
      out << pad << "time slab:\n";
      for (const auto& h : node["time"]) out << pad << "  " << h["text"].get<std::string>() << "\n";
    } else {
      const auto& item = *node.begin();
      out << pad << node.begin().key() << " of\n";
      for (const auto& c : item) tree(c, depth + 1);
    }
  };
  for (const auto& span : report["spans"]) {
    out << "sub-span " << span["t"][0].get<std::string>() << " <= t <= " << span["t"][1].get<std::string>() << "\n";
    for (const auto& o : span["objects"]) {
      if (o.contains("pose")) {   // a scene where something turns
        out << "  object " << printable(o["name"].get<std::string>()) << ": " << o["pose"]["text"].get<std::string>() << "\n";
        tree(o["tree"], 2);
        continue;
      }
      const auto &v = o["velocity"], &c = o["offset"];
      out << "  object " << printable(o["name"].get<std::string>()) << ": D(t) = (" << v[0].get<std::string>() << ", "
          << v[1].get<std::string>() << ", " << v[2].get<std::string>() << ") t + (" << c[0].get<std::string>()
          << ", " << c[1].get<std::string>() << ", " << c[2].get<std::string>() << ")\n";
      tree(o["tree"], 2);
    }
  }
}


json point_json(const std::array<std::string, 4>& p) { return json(p); }

// The generic points that make a closed witness or an earliest contact
// checkable (Pair_answer): one per object, in the order of "objects".
json cells_json(const std::array<std::array<std::string, 4>, 2>& cells)
{
  return json::array({point_json(cells[0]), point_json(cells[1])});
}

json check_json(const Check_answer& a, const Check_options& o, bool stats, double tolerance, const std::string& certificate,
                const std::vector<Mesh_record>& meshes)
{
  bool closed = a.semantics == Semantics::closed;
  json j = {{"collide", a.collide}, {"number", a.number}, {"semantics", semantics_name(a.semantics)}};
  if (a.number == "double") j["tolerance"] = tolerance;
  auto witness_json = [&](const Pair_answer& p) {
    json w{{"objects", {p.a, p.b}}, {"point", p.witness}, {"verified", p.witness_verified}};
    if (closed) w["inside"] = cells_json(p.witness_cells);
    if (!p.depth.empty()) w["depth"] = p.depth;
    return w;
  };
  auto earliest_json = [](const Pair_answer& p) {
    return json{{"t", p.t_star}, {"point", p.contact}, {"at_start", p.at_start}, {"inside", cells_json(p.contact_cells)}};
  };
  const Pair_answer* main = a.reported();
  if (main) j["witness"] = witness_json(*main);
  if (main && o.earliest) {
    j["earliest"] = earliest_json(*main);
    j["earliest"]["objects"] = {main->a, main->b};
  }
  if (o.all_pairs) {
    j["pairs"] = json::array();
    for (const auto& p : a.pairs) {
      json e = {{"objects", {p.a, p.b}}, {"witness", witness_json(p)}};
      if (o.earliest) e["earliest"] = earliest_json(p);
      j["pairs"].push_back(e);
    }
  }
  if (!certificate.empty()) j["certificate"] = certificate;
  if (stats) j["stats"] = stats_json(a.stats);
  if (stats && !meshes.empty()) j["stats"]["meshes"] = meshes_json(meshes);
  return j;
}

// How deep each regularised exact collision is at its witness
// (exact/Witness_depth.h): a user reads a 2.4 um overlap as one.
void add_depths(const Scene& scene, Check_answer& answer)
{
  if (answer.number == "double" || answer.semantics != Semantics::regularised || answer.pairs.empty()) return;
  Witness_depth depth(scene);
  auto index = [&](const std::string& name) {
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
      if (scene.objects[i].name == name) return static_cast<int>(i);
    return -1;
  };
  for (Pair_answer& p : answer.pairs) {
    std::array<Rational, 4> w;
    for (int c = 0; c < 4; ++c) w[c] = rational_from_string(p.witness[c]);
    std::optional<Rational> d = depth(index(p.a), index(p.b), w);
    if (d) p.depth = to_string(*d);
  }
}

std::string point_text(const std::array<std::string, 4>& p)
{
  return "x = " + p[0] + ", y = " + p[1] + ", z = " + p[2] + ", t = " + p[3];
}

void print_check(const Check_answer& a, const Check_options& o, bool stats, double tolerance, std::ostream& out,
                 const std::string& certificate, const std::vector<Mesh_record>& meshes)
{
  // The earliest pair's witness is the one shown when --earliest is given.
  const Pair_answer* main = a.reported();
  if (o.json) {
    out << check_json(a, o, stats, tolerance, certificate, meshes).dump(2) << "\n";
    return;
  }
  bool closed = a.semantics == Semantics::closed;
  std::string how = a.number + (closed ? ", closed semantics" : "");
  if (!a.collide) out << "no collision (" << how << (closed ? ": the closed objects do not meet" : "") << ")\n";
  for (const auto& p : a.pairs) {
    if (!o.all_pairs && &p != main) continue;
    out << (closed ? "contact or collision: " : "collision: ") << printable(p.a) << " and " << printable(p.b) << " (" << how << ")\n";
    out << (closed ? "  common point: " : "  witness: ") << point_text(p.witness)
        << (p.witness_verified ? "" : "  [NOT verified: fails the check against the scene]") << "\n";
    if (closed) {
      out << "    in the closure of the cell of " << p.a << " at " << point_text(p.witness_cells[0]) << "\n";
      out << "    in the closure of the cell of " << p.b << " at " << point_text(p.witness_cells[1]) << "\n";
    }
    if (p.earliest)
      out << (closed ? "  first contact: t* = " : "  earliest: t* = ") << p.t_star << " at x = " << p.contact[0]
          << ", y = " << p.contact[1] << ", z = " << p.contact[2]
          << (p.at_start ? "  (already in contact at the start of the span)" : "") << "\n";
  }
  if (o.earliest && main && o.all_pairs) out << "earliest pair: " << printable(main->a) << " and " << printable(main->b) << "\n";
  if (!certificate.empty()) out << "certificate: " << certificate << " (check it: clash4d verify SCENE " << certificate << ")\n";
  if (stats) {
    out << "stats:\n";
    json s = stats_json(a.stats);
    for (const auto& item : s.items()) out << "  " << item.key() << ": " << item.value().dump() << "\n";
    if (!meshes.empty()) out << "  meshes:\n" << meshes_text(meshes, "    ");
  }
}

void print_skeleton(const Skeleton_answer& a, bool as_json, std::ostream& out)
{
  if (as_json) {
    json pairs = json::array();
    for (const auto& p : a.pairs) pairs.push_back({{"objects", {p.a, p.b}}, {"edges", p.edges}});
    out << json{{"number", a.number}, {"collide", !a.pairs.empty()}, {"pairs", pairs}}.dump(2) << "\n";
    return;
  }
  if (a.pairs.empty()) out << "no collision (" << a.number << "): the collision region is empty\n";
  for (const auto& p : a.pairs) {
    out << "collision region of " << printable(p.a) << " and " << printable(p.b) << " (" << a.number << "): " << p.edges.size() << " edges\n";
    for (const auto& e : p.edges)
      out << "  (" << e[0][0] << ", " << e[0][1] << ", " << e[0][2] << ", " << e[0][3] << ") -- (" << e[1][0] << ", "
          << e[1][1] << ", " << e[1][2] << ", " << e[1][3] << ")\n";
  }
}

// A comparison under its title (the scene's file, or the file and query).
void print_comparison(const Comparison& c, const std::string& title, std::ostream& out)
{
  // Scenes are compared in two semantics, so closed subjects are marked; a
  // CCD query has only the closed one.
  bool marked = c.find("exact closed") != nullptr;
  out << title << (c.has_disagreement() ? ": DISAGREEMENT\n" : ": all subjects agree\n");
  for (const Subject_row& s : c.subjects) {
    out << "  " << s.subject << (marked && s.semantics == "closed" && s.subject != "exact closed" ? " [closed]" : "") << ": ";
    if (s.failed()) {
      out << "failed: " << s.error << (s.cause ? "  <- " + *s.cause : "") << "\n";
      continue;
    }
    if (s.skipped) { out << "skipped: " << *s.skipped << "\n"; continue; }
    out << (s.collide.value_or(false) ? "collision" : "no collision");
    if (s.witness_valid) out << (*s.witness_valid ? ", witness valid" : ", witness INVALID");
    if (s.earliest) out << ", t* = " << with_decimal(s.earliest->t);
    if (s.t_error) out << " (error " << *s.t_error << ")";
    if (s.cause) out << "  <- " << *s.cause;
    out << "\n";
  }
}

int compare_scene_file(const std::string& f, const Compare_options& o, bool as_json, json& all, std::ostream& out,
                       std::ostream& err, Progress_line& shown)
{
  Scene scene;
  if (load(f, scene, err)) return CLASH4D_EXIT_INVALID;
  return guarded(f, err, [&] {
    Compare_options shown_o = o;
    shown_o.on_subject = [&](const std::string& subject) { shown.show(f + ": " + subject); };
    Comparison c = compare_scene(scene, f, shown_o);
    shown.clear();
    if (as_json) all.push_back(c.to_json()); else print_comparison(c, f, out);
    return c.has_disagreement() ? 1 : 0;
  });
}

// Every query of a CCD file, read whole first: bad input is exit 2 naming
// the place, never a partial list.
int compare_ccd_file(const std::string& f, const Ccd_compare_options& o, std::optional<Ccd_type> type, bool as_json,
                     json& all, std::ostream& out, std::ostream& err)
{
  std::vector<Ccd_query> queries;
  try {
    queries = read_ccd_queries(f, type);
  } catch (const Input_error& e) {
    err << e.format(f) << "\n";
    return e.exit_code();
  }
  return guarded(f, err, [&] {
    int status = 0;
    for (std::size_t i = 0; i < queries.size(); ++i) {
      Ccd_comparison c = compare_query(queries[i], f, i, o);
      if (as_json) all.push_back(c.to_json()); else print_comparison(c.comparison, f + ": " + c.comparison.name, out);
      if (c.comparison.has_disagreement()) status = 1;
    }
    return status;
  });
}

// Scene files and CCD query files (compare/Ccd_query_files.h), in order.
int compare(const std::vector<std::string>& files, const Compare_options& o, const Ccd_compare_options& ccd,
            std::optional<Ccd_type> type, bool as_json, std::ostream& out, std::ostream& err)
{
  int status = 0;
  json all = json::array();
  Progress_line shown(progress_mode_of_stderr(), err, "clash4d compare");
  for (const auto& f : files) {
    int s = is_ccd_query_file(f) ? compare_ccd_file(f, ccd, type, as_json, all, out, err)
                                 : compare_scene_file(f, o, as_json, all, out, err, shown);
    if (s == 1 && status == 0) status = 1;
    if (s > 1) status = s;
  }
  if (as_json) out << all.dump(2) << "\n";
  return status;
}

// Writes to a temporary name and renames, so no half-written scene is left.
int generate(int n, int colliding, std::uint64_t seed, const std::string& file, std::ostream& out, std::ostream& err)
{
  Grid_scene g;
  try {
    g = make_grid_scene(n, colliding, seed);
  } catch (const std::invalid_argument& e) {
    err << "clash4d generate: " << e.what() << "\n";
    return CLASH4D_EXIT_INVALID;
  }
  if (file.empty()) {
    out << g.json;
    return 0;
  }
  try {
    write_file_atomically(file, g.json);
  } catch (const std::runtime_error& e) {
    err << "clash4d generate: " << e.what() << "\n";
    return CLASH4D_EXIT_INVALID;
  }
  out << file << ": " << n << " blocks; colliding by construction:";
  for (const auto& p : g.colliding) out << " b" << p.first << "/b" << p.second;
  out << "\n";
  return 0;
}

// The instantiation --number names: one dispatch for check, skeleton and
// extrude.
struct Instantiation {
  Check_answer (*check)(const Scene&, const Check_options&, double tolerance);
  Skeleton_answer (*skeleton)(const Scene&);
  json (*extrude)(const Scene&);
};

const Instantiation& instantiation(const std::string& number)
{
  static const Instantiation exact{[](const Scene& s, const Check_options& o, double) { return check_exact(s, o); },
                                   skeleton_exact, extrude_exact};
  static const Instantiation rational{[](const Scene& s, const Check_options& o, double) { return check_rational(s, o); },
                                      skeleton_rational, extrude_rational};
  static const Instantiation dbl{[](const Scene& s, const Check_options& o, double tol) { return check_double(s, tol, o); },
                                 skeleton_double, extrude_double};
  return number == "exact" ? exact : number == "rational" ? rational : dbl;
}

const char* const number_help =
    "number type: exact (default; interval filter with exact rational fallback), rational (every sign in "
    "rationals: the reference, same answers, slower) or double";

// What a subcommand does once its options are parsed: the exit status.
using Command = std::function<int()>;

// Options shared by the commands that read one scene and run one
// instantiation (extrude, check, skeleton).
struct Scene_args {
  std::string file, number = "exact";
  bool as_json = false;
};

CLI::App* add_scene_command(CLI::App& app, const char* name, const char* help, Scene_args& a)
{
  CLI::App* cmd = app.add_subcommand(name, help);
  cmd->add_option("SCENE", a.file, "scene file")->required();
  cmd->add_option("--number", a.number, number_help)->check(CLI::IsMember({"exact", "rational", "double"}));
  return cmd;
}

// Reads the scene and runs `run(scene)` guarded (exit status as the spec says).
template <class Run>
int with_scene(const Scene_args& a, std::ostream& err, Run run)
{
  Scene scene;
  if (int s = load(a.file, scene, err)) return s;
  return guarded(a.file, err, [&] { return run(scene); });
}

Command add_validate(CLI::App& app, std::ostream& out, std::ostream& err)
{
  auto files = std::make_shared<std::vector<std::string>>();
  CLI::App* cmd = app.add_subcommand("validate", "Check scene files against the scene format; exit 0 when all are valid, 2 otherwise.");
  cmd->add_option("SCENE", *files, "scene files")->required();
  return [cmd, files, &out, &err] { return cmd->parsed() ? validate(*files, out, err) : -1; };
}

Command add_extrude(CLI::App& app, std::ostream& out, std::ostream& err)
{
  auto a = std::make_shared<Scene_args>();
  CLI::App* cmd = add_scene_command(app, "extrude", "Print every object's space-time half-space tree per constant-velocity time sub-span (paper §2-3).", *a);
  cmd->add_flag("--json", a->as_json, "print JSON (numbers as exact strings)");
  return [cmd, a, &out, &err] {
    if (!cmd->parsed()) return -1;
    return with_scene(*a, err, [&](const Scene& scene) {
      json report;
      if (scene_rotates(scene)) {
        // Polynomials in t are printed exactly (rotation/Rotating_extrusion.h).
        if (a->number == "double") refuse_rotation(scene, "it turns, and extrude prints its polynomials exactly only (--number exact or rational, not double)");
        report = rotating_extrusion(scene);
        report["number"] = a->number;   // exact or rational: the same exact polynomials
      } else {
        report = instantiation(a->number).extrude(scene);
      }
      if (a->as_json) out << report.dump(2) << "\n"; else print_extrusion_text(report, out);
      return 0;
    });
  };
}

struct Check_args : Scene_args {
  Check_options options;
  std::string certificate;
  double certificate_max_mb = 256;
  double tolerance = 0;
  bool stats = false, no_sbounds = false, no_convex_lp = false;
  std::string semantics = "regularised";
};

const char* const semantics_help =
    "regularised (default): a collision is a common interior point, touching is not one; closed: the objects' closed "
    "sets (closure of the interior) meet within the closed span, touching counts (scene-format.md, Closed semantics)";

// The certificate of a turning scene's answer (certify/Turning_certificate.h),
// written before the answer is printed.
std::function<void(const Rotating_check_answer&)> turning_certificate_writer(const Scene& scene, const Check_args& a)
{
  return [&scene, &a](const Rotating_check_answer& answer) {
    auto max = static_cast<std::size_t>(a.certificate_max_mb * 1024 * 1024);
    try {
      Slow_step_note note("writing the certificate " + a.certificate);   // a turning proof can take minutes
      write_certificate(a.certificate, make_turning_certificate(scene, answer, a.options), max);
    } catch (const Certificate_limit& e) {
      throw Input_error("certificate", e.what(), CLASH4D_EXIT_LIMIT);
    } catch (const Turning_proof_missing& e) {
      refuse_rotation(scene, std::string("no certificate was written: ") + e.what());
    } catch (const Minor_limit& e) {   // the proofs' critical times are over whole objects
      throw Input_error("certificate", std::string("no certificate was written: ") + e.what(), CLASH4D_EXIT_LIMIT);
    }
  };
}

Command add_check(CLI::App& app, std::ostream& out, std::ostream& err)
{
  auto a = std::make_shared<Check_args>();
  CLI::App* cmd = add_scene_command(app, "check", "Decide whether any pair of objects collides (regularised: touching is not a collision).", *a);
  cmd->add_option("--tolerance", a->tolerance, "double only: treat |value| <= EPS as zero (default 0)")->check(CLI::NonNegativeNumber);
  cmd->add_flag("--all-pairs", a->options.all_pairs, "list every colliding pair instead of stopping at the first");
  cmd->add_flag("--earliest", a->options.earliest,
                "find the earliest collision time t* (exact) and a contact point (§5); closed: the first contact time");
  cmd->add_option("--semantics", a->semantics, semantics_help)->check(CLI::IsMember({"regularised", "closed"}));
  cmd->add_flag("--json", a->as_json, "print one JSON object (spec: check)");
  cmd->add_flag("--stats", a->stats, "report what each stage did");
  cmd->add_flag("--no-sbounds", a->no_sbounds,
                "bound by the paper's original procedure (boxes at velocity changes) instead of S-bounds; for reproducing §4.1");
  cmd->add_flag("--no-convex-lp", a->no_convex_lp,
                "search pairs of convex objects with the paper's cascade too, instead of deciding them by linear "
                "programs first (beyond the paper); for reproducing the paper's statistics");
  cmd->add_option("--certificate", a->certificate,
                  "also write a proof of the answer to FILE, checkable by 'clash4d verify SCENE FILE' "
                  "(exact kernels only; docs/certificate-format.md)");
  cmd->add_option("--certificate-max-mb", a->certificate_max_mb, "refuse (exit 3) a certificate larger than this (default 256)")
      ->check(CLI::PositiveNumber)->check(CLI::Range(0.0, 1048576.0));
  return [cmd, a, &out, &err] {
    if (!cmd->parsed()) return -1;
    if (a->tolerance != 0 && a->number != "double") {
      err << "clash4d: --tolerance applies to --number double only\n";
      return CLASH4D_EXIT_INVALID;
    }
    if (!a->certificate.empty() && a->number == "double") {
      err << "clash4d: --certificate needs an exact answer (--number exact or rational)\n";
      return CLASH4D_EXIT_INVALID;
    }
    std::error_code same;
    if (!a->certificate.empty() && std::filesystem::equivalent(a->certificate, a->file, same)) {
      err << "clash4d check: --certificate " << a->certificate << " is the scene file itself; refusing to write over "
          << "the input\n";
      return CLASH4D_EXIT_INVALID;
    }
    a->options.sbounds = !a->no_sbounds;
    a->options.convex_lp = !a->no_convex_lp;
    a->options.json = a->as_json;
    a->options.stage_seconds = a->stats;   // the stage clocks are read only when printed
    a->options.semantics = *semantics_from_name(a->semantics);
    return with_scene(*a, err, [&](const Scene& scene) {
      if (scene_rotates(scene)) {   // time slices (rotation/), regularised-semantics.md facts 9-12
        Rotating_check_request r{a->file, a->number, a->options, a->stats, a->tolerance, {}};
        // The certificate's pieces are checked each on its own (docs/
        // certificate-format.md, 8.3), so the writer cuts the span where
        // check does (two convex pieces: their feature minors' roots).
        if (!a->certificate.empty()) r.before_print = turning_certificate_writer(scene, *a);
        return run_rotating_check(scene, r, out);
      }
      Check_answer answer = instantiation(a->number).check(scene, a->options, a->tolerance);
      if (a->as_json) add_depths(scene, answer);
      if (!a->certificate.empty()) {
        // Before the answer is printed: a certificate that cannot be made
        // leaves no answer behind it (exit 3 names the limit).
        try {
          auto max = static_cast<std::size_t>(a->certificate_max_mb * 1024 * 1024);
          Slow_step_note note("writing the certificate " + a->certificate);
          write_certificate(a->certificate, make_certificate(scene, answer, a->options), max);
        } catch (const Certificate_limit& e) {
          err << a->file << ": " << e.what() << " (exit 3)\n";
          return CLASH4D_EXIT_LIMIT;
        }
      }
      print_check(answer, a->options, a->stats, a->tolerance, out, a->certificate, scene.meshes);
      return answer.collide ? 1 : 0;
    });
  };
}

struct Skeleton_args : Scene_args {
  std::string semantics = "regularised";
};

Command add_skeleton(CLI::App& app, std::ostream& out, std::ostream& err)
{
  auto a = std::make_shared<Skeleton_args>();
  CLI::App* cmd = add_scene_command(app, "skeleton", "Print every edge of the boundary of each colliding pair's collision region in space-time (§5; a full search, slower than check).", *a);
  cmd->add_flag("--json", a->as_json, "print JSON (numbers as exact strings)");
  cmd->add_option("--semantics", a->semantics,
                  "regularised only: the skeleton is that of the (open) collision region; for contact use check "
                  "--semantics closed")
      ->check(CLI::IsMember({"regularised", "closed"}));
  return [cmd, a, &out, &err] {
    if (!cmd->parsed()) return -1;
    if (a->semantics == "closed") {
      // The closed touching set may be of any dimension (a point, a face):
      // it has no skeleton of edges in the paper's sense (§5).
      err << "clash4d skeleton: --semantics closed is not supported: the skeleton is that of the regularised "
             "collision region; use 'clash4d check --semantics closed' for contact\n";
      return CLASH4D_EXIT_INVALID;
    }
    return with_scene(*a, err, [&](const Scene& scene) {
      refuse_rotation(scene, rotation_unsupported_by("skeleton"));
      Skeleton_answer answer = instantiation(a->number).skeleton(scene);
      print_skeleton(answer, a->as_json, out);
      return answer.pairs.empty() ? 0 : 1;
    });
  };
}

struct Compare_args {
  std::vector<std::string> files;
  Builtin_subject_args builtin;
  bool earliest = false, as_json = false;
  std::string semantics = "regularised";
  Ccd_compare_args ccd;
  Subject_args subjects;
};

const char* const own_semantics_help =
    "the semantics of the toolkit's own float subjects (double, double tol=EPS, exact-rounded): regularised (default) "
    "or closed; every subject is judged against exact in its own semantics (fcl and bullet: closed; --subject: as its "
    "hello line says)";

Command add_compare(CLI::App& app, std::ostream& out, std::ostream& err)
{
  auto a = std::make_shared<Compare_args>();
  CLI::App* cmd = app.add_subcommand("compare", "Run exact, double, double with tolerances and exact-on-rounded-input on each scene or CCD query; flag and classify every disagreement with exact (exit 1 when any).");
  cmd->add_option("FILE", a->files, "scene files, and CCD query files (.csv, or JSON lines of queries: docs/ccd-queries.md), one comparison per query")->required();
  add_builtin_subject_options(*cmd, a->builtin);
  cmd->add_flag("--earliest", a->earliest, "also compare earliest collision times t*");
  cmd->add_flag("--json", a->as_json, "print one JSON object per scene or query in a list");
  cmd->add_option("--semantics", a->semantics, own_semantics_help)->check(CLI::IsMember({"regularised", "closed"}));
  add_ccd_options(*cmd, a->ccd);
  add_subject_options(*cmd, a->subjects);
  return [cmd, a, &out, &err] {
    if (!cmd->parsed()) return -1;
    Compare_options o;
    o.semantics = *semantics_from_name(a->semantics);
    apply_builtin_subject_args(a->builtin, o);
    o.earliest = a->earliest;
    o.time_bound = a->ccd.time_bound;
    if (!apply_subject_args(a->subjects, o, "compare", err)) return CLASH4D_EXIT_INVALID;
    return compare(a->files, o, ccd_options_of(o, a->ccd), ccd_type_of(a->ccd), a->as_json, out, err);
  };
}

struct Fuzz_args {
  Fuzz_options fuzz;
  std::string shard;
  std::uint64_t shard_count = 0;
  std::vector<std::string> merge_dirs;
  Builtin_subject_args builtin;
  std::string semantics = "regularised";
  bool ccd = false, earliest = false;
  Ccd_compare_args ccd_args;
  Subject_args subjects;
};

// fuzz --ccd: the same campaign over CCD queries; the scenes' own options
// (--fcl, bullet, --semantics) have no meaning there.
int ccd_fuzz(const Fuzz_args& a, const CLI::App& cmd, std::ostream& out, std::ostream& err)
{
  if (a.fuzz.compare.fcl || a.fuzz.compare.bullet || cmd.count("--semantics")) {
    err << "clash4d fuzz: --fcl, --subject fcl or bullet and --semantics are for scenes: CCD queries have one "
           "semantics (closed) and no library subject\n";
    return CLASH4D_EXIT_INVALID;
  }
  Ccd_fuzz_options c;
  static_cast<Campaign_options&>(c) = a.fuzz;
  Compare_options scenes = a.fuzz.compare;
  scenes.earliest = a.earliest;
  c.compare = ccd_options_of(scenes, a.ccd_args);
  return fuzz_command(c, out, err);
}

Command add_fuzz(CLI::App& app, std::ostream& out, std::ostream& err)
{
  auto a = std::make_shared<Fuzz_args>();
  CLI::App* cmd = app.add_subcommand("fuzz", "A deterministic campaign of contact cases against exact arithmetic; saves and shrinks every disagreement in DIR (resumable; exit 1 when any finding).");
  cmd->add_option("--seed", a->fuzz.seed, "campaign seed");
  cmd->add_option("--cases", a->fuzz.cases, "number of cases in the whole campaign");
  cmd->add_option("--shard", a->shard, "K/S: run the K-th of S disjoint parts (default: from the scheduler, else 1/1)");
  cmd->add_option("--shard-count", a->shard_count,
                  "S, without --shard: this is shard K of S with K from SLURM_ARRAY_TASK_ID (minus SLURM_ARRAY_TASK_MIN, "
                  "plus 1) or JOB_COMPLETION_INDEX (plus 1); Slurm's SLURM_ARRAY_TASK_COUNT gives S when omitted");
  cmd->add_option("--out", a->fuzz.out, "output folder")->required();
  add_builtin_subject_options(*cmd, a->builtin);
  cmd->add_option("--merge", a->merge_dirs, "join these fuzz output folders into --out instead of running");
  cmd->add_option("--semantics", a->semantics, own_semantics_help)->check(CLI::IsMember({"regularised", "closed"}));
  cmd->add_flag("--ccd", a->ccd,
                "a campaign of CCD queries (ccd/Ccd_families.h, every family) instead of scenes; findings are also "
                "written in the benchmark's CSV (docs/ccd-queries.md)");
  cmd->add_flag("--rotation", a->fuzz.rotation,
                "a campaign of turning parts (compare/Rotation_families.h: corners and edges reaching faces at rational "
                "and irrational instants, doors, pockets, flush faces) instead of the contact families");
  cmd->add_flag("--earliest", a->earliest, "--ccd: also compare t* (a disagreement of cause time beyond --time-bound)");
  cmd->add_option("--time-bound", a->ccd_args.time_bound,
                  "--ccd --earliest: the largest |t - t*| that is no disagreement (default 1e-9)")
      ->check(CLI::NonNegativeNumber);
  add_subject_options(*cmd, a->subjects);
  return [cmd, a, &out, &err] {
    if (!cmd->parsed()) return -1;
    Fuzz_options& fuzz = a->fuzz;
    if (!a->merge_dirs.empty()) return merge_command(a->merge_dirs, fuzz.out, out, err);
    if (!resolve_shard(a->shard, a->shard_count, std::getenv, fuzz, err)) return CLASH4D_EXIT_INVALID;
    apply_builtin_subject_args(a->builtin, fuzz.compare);
    fuzz.compare.semantics = *semantics_from_name(a->semantics);
    if (!apply_subject_args(a->subjects, fuzz.compare, "fuzz", err)) return CLASH4D_EXIT_INVALID;
    fuzz.progress = progress_mode_of_stderr();
    if (a->ccd && fuzz.rotation) {
      err << "clash4d fuzz: --ccd and --rotation are two kinds of campaign: choose one\n";
      return CLASH4D_EXIT_INVALID;
    }
    if (a->ccd) return ccd_fuzz(*a, *cmd, out, err);
    if (a->earliest || cmd->count("--time-bound")) {
      err << "clash4d fuzz: --earliest and --time-bound are for --ccd campaigns\n";
      return CLASH4D_EXIT_INVALID;
    }
    return fuzz_command(fuzz, out, err);
  };
}

struct Report_args {
  std::vector<std::string> inputs;
  std::string out;
  Builtin_subject_args builtin;
  bool fresh = false;
  std::string semantics = "regularised";
  Ccd_compare_args ccd;
  Subject_args subjects;
};

Command add_report(CLI::App& app, std::ostream& out, std::ostream& err)
{
  auto a = std::make_shared<Report_args>();
  CLI::App* cmd = app.add_subcommand("report", "Compare scenes and CCD queries (files, folders, fuzz outputs) and write DIR/index.html, report.json and junit.xml.");
  cmd->add_option("INPUT", a->inputs, "scene files, CCD query files (.csv or JSON lines), folders of them, or fuzz output folders (fuzz --ccd's too)")->required();
  cmd->add_option("--out", a->out, "output folder")->required();
  cmd->add_option("--semantics", a->semantics, own_semantics_help)->check(CLI::IsMember({"regularised", "closed"}));
  add_builtin_subject_options(*cmd, a->builtin);
  cmd->add_flag("--fresh", a->fresh,
                "compare every scene again, instead of taking the comparisons DIR/cases keeps from an earlier or "
                "interrupted run of the same report (they are reused only for the same scene and options)");
  add_ccd_options(*cmd, a->ccd);
  add_subject_options(*cmd, a->subjects);
  return [cmd, a, &out, &err] {
    if (!cmd->parsed()) return -1;
    Compare_options o;
    apply_builtin_subject_args(a->builtin, o);
    o.earliest = true;
    o.time_bound = a->ccd.time_bound;
    o.semantics = *semantics_from_name(a->semantics);
    if (!apply_subject_args(a->subjects, o, "report", err)) return CLASH4D_EXIT_INVALID;
    Report_inputs inputs{a->inputs, o, ccd_options_of(o, a->ccd), ccd_type_of(a->ccd), allowed_mesh_folders};
    inputs.fresh = a->fresh;
    inputs.progress = progress_mode_of_stderr();
    return report_command(inputs, a->out, out, err);
  };
}

struct Generate_args {
  int n = 0, colliding = 0;
  std::uint64_t seed = 1;
  std::string out;
};

Command add_generate(CLI::App& app, std::ostream& out, std::ostream& err)
{
  auto a = std::make_shared<Generate_args>();
  CLI::App* cmd = app.add_subcommand("generate", "Write a scaling scene: N unit blocks on a grid, K pairs of which collide from t* = 5 on (§6 benchmark).");
  cmd->add_option("--n", a->n, "number of blocks")->required()->check(CLI::Range(2, 1000000));
  cmd->add_option("--colliding", a->colliding, "colliding pairs (disjoint x-neighbours)")->check(CLI::NonNegativeNumber);
  cmd->add_option("--seed", a->seed, "random seed (motions and which pairs collide)");
  cmd->add_option("--out", a->out, "output file (default: standard output)");
  return [cmd, a, &out, &err] { return cmd->parsed() ? generate(a->n, a->colliding, a->seed, a->out, out, err) : -1; };
}

} // namespace

int run_cli(int argc, const char* const* argv, std::ostream& out, std::ostream& err)
{
  CLI::App app(about, "clash4d");
  app.require_subcommand(1);
  allowed_mesh_folders.clear();   // run() may be called again in one process (tests)
  app.failure_message(CLI::FailureMessage::help);
  // In the order --help lists them; each says -1 when it was not the one given.
  std::vector<Command> commands{add_validate(app, out, err), add_extrude(app, out, err), add_check(app, out, err),
                                add_skeleton(app, out, err),  add_compare(app, out, err), add_fuzz(app, out, err),
                                add_report(app, out, err),    add_generate(app, out, err), add_verify(app, out, err),
                                add_ccd(app, out, err)};
  // The work budget (run/Work_budget.h), on the commands that search.
  double max_seconds = 0;
  for (const char* name : {"check", "skeleton", "compare", "fuzz", "report", "ccd"})
    app.get_subcommand(name)
        ->add_option("--max-seconds", max_seconds,
                     "stop with exit 3 when the run takes longer than S seconds, printing no answer (fuzz: saved "
                     "up to its last finished batch, resumable; default: unlimited)")
        ->check(CLI::PositiveNumber);
  for (const char* name : {"validate", "extrude", "check", "skeleton", "compare", "report"})
    app.get_subcommand(name)
        ->add_option("--allow-mesh-path", allowed_mesh_folders,
                     "let the scene's mesh files be under DIR too (repeatable; by default a mesh file must be under "
                     "the scene's own folder, docs/meshes.md)")
        ->type_name("DIR")->allow_extra_args(false)->check(CLI::ExistingDirectory.description(""));
  // The worker threads (TBB): answers do not depend on them (issue 60's
  // determinism test runs with 1 and with all).
  std::size_t threads = 0;
  for (const char* name : {"check", "skeleton", "compare", "fuzz", "report", "ccd"})
    app.get_subcommand(name)
        ->add_option("--threads", threads, "run on at most N threads (default: every core); the answers are the same")
        ->check(CLI::PositiveNumber);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) {   // --help
      out << (app.get_subcommands().empty() ? app.help() : app.get_subcommands().front()->help());
      return 0;
    }
    err << "clash4d: " << e.what() << "\n" << "run 'clash4d --help' or 'clash4d COMMAND --help'\n";
    return CLASH4D_EXIT_INVALID;
  }
  Work_budget::start(max_seconds);
  std::optional<tbb::global_control> limit;
  if (threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, threads);
  try {
    for (const Command& run : commands)
      if (int status = run(); status >= 0) return status;
  } catch (const Budget_exceeded& e) {
    std::string name = app.get_subcommands().front()->get_name();
    err << "clash4d " << name << ": the work budget of --max-seconds " << e.seconds
        << " ran out before an answer (exit 3)"
        << (name == "fuzz" ? "; the campaign is saved up to its last finished batch: run the same command again to "
                             "resume"
                           : "")
        << "\n";
    return CLASH4D_EXIT_LIMIT;
  }
  return CLASH4D_EXIT_INVALID;   // require_subcommand makes this unreachable
}

} // namespace clash4d
