// What the viewer shows and edits, without any OpenGL: the mesh, the light setup and its
// highlight lines, the picked region, the regions found by the detection, the fairing running
// in a worker thread, and the undo history. The window (highlight_lines_viewer.cpp) draws this
// state and turns mouse, keys, ImGui widgets and script lines into calls of its members.
#ifndef HIGHLIGHT_LINES_DEMO_VIEWER_SESSION_H
#define HIGHLIGHT_LINES_DEMO_VIEWER_SESSION_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Highlight_lines/Highlight_line_sweeper.h>
#include <CGAL/Highlight_lines/default_light_setup.h>
#include <CGAL/Highlight_lines/fairing_building_blocks.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/detect_highlight_line_irregularities.h>
#include <CGAL/fair_with_highlight_lines.h>
#include <CGAL/Highlight_lines/internal/vector3.h>

#include "mesh_io.h"
#include "mesh_picture.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace viewer {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Face_index Face;
typedef Mesh::Vertex_index Vertex;
typedef Mesh::Edge_index Edge;
typedef Mesh::Halfedge_index Halfedge;
namespace HL = CGAL::Highlight_lines;
namespace HLP = CGAL::Highlight_lines::parameters;
typedef HL::Light_setup<K> Lights;
// Normals cached once per mesh position; the passes over vertices, edges and faces on all cores
// when TBB is linked.
typedef HL::Highlight_line_sweeper<Mesh, CGAL::Default, CGAL::Default,
                                   CGAL::Parallel_if_available_tag>
    Sweeper;
typedef std::vector<std::vector<Point>> Polylines;
// The segments of the lines as pairs of indices into their points, as OpenGL draws GL_LINES.
typedef std::vector<std::array<unsigned int, 2>> Segments;

// The light setup as the user moves it: a reference setup (the light tunnel placed over the mesh
// when it is loaded) turned, tilted, moved across the lights and respaced. Keeping the four
// values rather than the moved setup lets a slider or a script set each one absolutely.
struct Light_controls
{
  double angle_degrees = 0; // rotation of the light direction H in the light plane, about Z
  double tilt_degrees = 0;  // rotation of the light plane about H
  double offset = 0;        // translation across the lights, in spacings
  double spacing = 1;       // distance between adjacent lights

  Lights applied_to(const Lights& reference) const
  {
    const double degree = 3.14159265358979323846 / 180;
    const Lights turned = reference.rotated(reference.plane_normal(), angle_degrees * degree);
    const Lights tilted = turned.rotated(turned.light_direction(), tilt_degrees * degree);
    const Lights respaced(tilted.base_point(), tilted.light_direction(), tilted.plane_normal(),
                          spacing);
    return respaced.translated(respaced.index_direction() * (offset * spacing));
  }
};

// A light setup with all the digits, and the level range the lines were computed for, in a small
// text file that a check program reads back.
inline bool write_lights(const std::string& path, const Lights& lights,
                         const std::optional<std::pair<long long, long long>>& levels)
{
  std::ofstream out(path);
  out.precision(17);
  out << "base " << lights.base_point() << "\ndirection " << lights.light_direction() << "\nnormal "
      << lights.plane_normal() << "\nspacing " << lights.spacing() << "\n";
  if (levels)
    out << "levels " << levels->first << ' ' << levels->second << "\n";
  return bool(out);
}

// CGAL's polylines format: the number of points, then their coordinates, one line each.
inline bool write_polylines(const std::string& path, const Polylines& polylines)
{
  std::ofstream out(path);
  out.precision(17);
  for (const auto& polyline : polylines) {
    out << polyline.size();
    for (const Point& p : polyline)
      out << ' ' << p;
    out << '\n';
  }
  return bool(out);
}

// The region's face ids, in the plain format the example programs read with --region.
inline bool write_face_ids(const std::string& path, const std::vector<Face>& faces)
{
  std::ofstream out(path);
  for (std::size_t i = 0; i < faces.size(); ++i)
    out << (i ? " " : "") << std::size_t(faces[i]);
  out << "\n";
  return bool(out);
}

// A ray, for picking.
struct Ray
{
  std::array<double, 3> origin, direction;
};

// The first face of `mesh` that `ray` hits (Möller–Trumbore on every face: a few milliseconds
// for a million faces, once per click, without building a tree that every fairing step would
// invalidate), with the hit point; nothing if it misses the mesh.
inline std::optional<std::pair<Face, Point>> first_hit(const Mesh& mesh, const Ray& ray)
{
  auto sub = [](const Point& a, const Point& b) {
    return std::array<double, 3>{a.x() - b.x(), a.y() - b.y(), a.z() - b.z()};
  };
  using CGAL::Highlight_lines::internal::vector3::cross;
  using CGAL::Highlight_lines::internal::vector3::dot;
  const Point origin(ray.origin[0], ray.origin[1], ray.origin[2]);
  double nearest = std::numeric_limits<double>::infinity();
  std::optional<std::pair<Face, Point>> hit;
  for (Face f : faces(mesh)) {
    const auto h = mesh.halfedge(f);
    const Point& a = mesh.point(mesh.source(h));
    const Point& b = mesh.point(mesh.target(h));
    const Point& c = mesh.point(mesh.target(mesh.next(h)));
    const auto e1 = sub(b, a), e2 = sub(c, a);
    const auto p = cross(ray.direction, e2);
    const double det = dot(e1, p);
    if (std::abs(det) < 1e-300)
      continue;
    const auto s = sub(origin, a);
    const double u = dot(s, p) / det;
    if (u < 0 || u > 1)
      continue;
    const auto q = cross(s, e1);
    const double v = dot(ray.direction, q) / det;
    if (v < 0 || u + v > 1)
      continue;
    const double t = dot(e2, q) / det;
    if (t > 0 && t < nearest) {
      nearest = t;
      hit = std::make_pair(f, Point(origin.x() + t * ray.direction[0],
                                    origin.y() + t * ray.direction[1],
                                    origin.z() + t * ray.direction[2]));
    }
  }
  return hit;
}

// The faces reached from `seed` across edges whose three corners lie within `radius` of
// `center`: a disc on the surface, which does not jump to the other side of a thin part as a
// plain distance test would.
inline std::vector<Face> grown_region(const Mesh& mesh, Face seed, const Point& center,
                                      double radius)
{
  auto inside = [&](Face f) {
    for (Vertex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      if (CGAL::squared_distance(mesh.point(v), center) > radius * radius)
        return false;
    return true;
  };
  std::vector<char> seen(num_faces(mesh), 0);
  std::vector<Face> region, front{seed};
  seen[std::size_t(seed)] = 1;
  if (!inside(seed))
    return {seed}; // a radius below the picked face still selects it
  while (!front.empty()) {
    const Face f = front.back();
    front.pop_back();
    region.push_back(f);
    for (auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const Face g = mesh.face(mesh.opposite(h));
      if (g != Mesh::null_face() && !seen[std::size_t(g)]) {
        seen[std::size_t(g)] = 1;
        if (inside(g))
          front.push_back(g);
      }
    }
  }
  std::sort(region.begin(), region.end());
  return region;
}

// What a running fairing reports to the window, under a mutex.
struct Fairing_progress
{
  std::vector<HL::Fairing_report::Iteration> iterations;
  std::vector<Point> positions; // of the mesh after the latest iteration
  bool new_positions = false;
};

// One background computation at a time (the fairing or the detection), so that the window keeps
// drawing while it runs. The worker owns a copy of the mesh; the window's mesh is only written by
// the window's thread.
class Background_job
{
public:
  ~Background_job() { wait(); }
  bool running() const { return running_; }
  bool finished() const { return started_ && !running_; }
  void request_cancel() { cancel_ = true; }
  bool cancel_requested() const { return cancel_; }
  void start(std::function<void()> work)
  {
    wait();
    cancel_ = false;
    running_ = true;
    started_ = true;
    thread_ = std::thread([this, work = std::move(work)] {
      work();
      running_ = false;
    });
  }
  // Joins the finished worker; afterwards finished() is false until the next start().
  void wait()
  {
    if (thread_.joinable())
      thread_.join();
    started_ = false;
  }

private:
  std::thread thread_;
  std::atomic<bool> running_{false}, cancel_{false};
  bool started_ = false;
};

class Session
{
public:
  Session() = default;
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
  // The worker uses the members: it stops before they go.
  ~Session()
  {
    job_.request_cancel();
    job_.wait();
  }

  // ---- The mesh -------------------------------------------------------------------------------

  // Reads a mesh (OFF, OBJ, PLY, STL) and places the light tunnel over it; false, with the
  // reason in `error`, if it cannot be read or has no triangle the lights can image.
  bool load(const std::string& path, std::string& error)
  {
    if (job_running()) {
      error = "a computation is running";
      return false;
    }
    Mesh mesh;
    if (!mesh_io::read_triangle_mesh(path, mesh)) {
      error = "cannot read a polygon mesh from " + path;
      return false;
    }
    return set_mesh(std::move(mesh), path, error);
  }
  // Shows `mesh` (a triangle mesh without removed elements), as read from `path`.
  bool set_mesh(Mesh&& mesh, const std::string& path, std::string& error)
  {
    if (job_running()) {
      error = "a computation is running";
      return false;
    }
    try {
      Lights reference = HL::default_light_setup(mesh, HLP::number_of_lines(40));
      auto sweeper = std::make_unique<Sweeper>(mesh_storage(std::move(mesh)));
      sweeper_ = std::move(sweeper);
      reference_lights_ = reference;
    } catch (const HL::Invalid_input& e) {
      error = e.what();
      return false;
    }
    path_ = path;
    creases_ = mesh_->add_property_map<Edge, bool>("e:viewer_crease", false).first;
    ++mesh_generation_;
    ++positions_revision_;
    controls_ = Light_controls();
    controls_.spacing = CGAL::to_double(reference_lights_->spacing());
    region_.clear();
    detected_.clear();
    history_.assign(1, positions());
    history_index_ = 0;
    compute_bounding_box();
    cut_ = mesh_picture::Cut_corners();
    if (crease_angle_) { // as asked for before this mesh
      update_creases();
      rebuild_sweeper();
    }
    update_normals();
    update_lines();
    return true;
  }
  bool has_mesh() const { return bool(sweeper_); }
  // Changes whenever something drawn changes (lines, positions, region, detected regions).
  std::size_t revision() const { return revision_; }
  // Changes whenever the vertex positions (and normals) change.
  std::size_t positions_revision() const { return positions_revision_; }
  // Changes with each mesh shown (its triangles, not only its positions).
  std::size_t mesh_generation() const { return mesh_generation_; }
  const Mesh& mesh() const { return *mesh_; }
  const std::string& path() const { return path_; }
  const std::array<double, 3>& box_center() const { return box_center_; }
  double box_diagonal() const { return box_diagonal_; }
  // Area-weighted vertex normals (the sum of the incident faces' cross products, eq. 3 of the
  // paper, as the sweeper computes them), unit length, 3 per vertex.
  const std::vector<double>& vertex_normals() const { return normals_; }

  // What the shading and the zebra are drawn on: one point per vertex, or, while the model is
  // cut along the creases, one per sector of faces between crease edges (the mesh cut as the
  // model is), so that the creases look sharp. The first points are the vertices, in order.
  std::size_t number_of_shading_points() const
  {
    return cut_.origin.empty() ? num_vertices(*mesh_) : cut_.origin.size();
  }
  // The vertex of a shading point.
  Vertex shading_origin(std::size_t point) const
  {
    return Vertex(Mesh::size_type(cut_.origin.empty() ? point : cut_.origin[point]));
  }
  // The shading point of target(h) in face(h).
  std::size_t shading_point(Halfedge h) const
  {
    return cut_.origin.empty() ? std::size_t(mesh_->target(h))
                               : cut_.point_of_corner[std::size_t(h)];
  }
  // Unit normals, 3 per shading point: the vertex normals, or the area-weighted normals of the
  // sectors.
  const std::vector<double>& shading_normals() const
  {
    return cut_.origin.empty() ? normals_ : sector_normals_;
  }
  // Changes whenever the shading points change (not their positions).
  std::size_t shading_generation() const { return shading_generation_; }

  // ---- The lights and their highlight lines ---------------------------------------------------

  const Lights& reference_lights() const { return *reference_lights_; }
  const Lights& lights() const { return *lights_; }
  const Light_controls& light_controls() const { return controls_; }
  // Moves the lights; false (lights unchanged, reason in `error`) for an invalid setup.
  bool set_light_controls(const Light_controls& controls, std::string& error)
  {
    if (!(controls.spacing > 0) || !std::isfinite(controls.spacing)) {
      error = "the spacing must be a positive number";
      return false;
    }
    const Light_controls old = controls_;
    controls_ = controls;
    try {
      update_lines();
    } catch (const HL::Invalid_input& e) {
      controls_ = old;
      update_lines();
      error = e.what();
      return false;
    }
    update_region_decorations(); // the desired lines follow the lights
    return true;
  }
  // Sets the light direction H (projected into the light plane) as a turn of the reference's.
  bool set_light_direction(const Vector& direction, std::string& error)
  {
    const Vector z = reference_lights_->plane_normal();
    const Vector in_plane = direction - (direction * z) * z;
    if (!(in_plane.squared_length() > 0)) {
      error = "the light direction must not be the light plane's normal";
      return false;
    }
    const Vector h = reference_lights_->light_direction();
    Light_controls c = controls_;
    c.angle_degrees = std::atan2(CGAL::cross_product(h, in_plane) * z, h * in_plane) * 180 /
                      3.14159265358979323846;
    return set_light_controls(c, error);
  }
  // Cuts the model along the creases: the edges whose faces' normals differ by more than
  // `degrees` (Polygon_mesh_processing::detect_sharp_edges(), found again whenever the mesh
  // moves), so that the lines of a CAD part run straight on its flat faces and end at its
  // creases (the library's crease_edge_map); none: the paper's model, one normal per vertex.
  // The shading and the zebra are cut the same way (shading_normals()). False (nothing
  // changed, the reason in `error`) for an angle outside (0, 180).
  bool set_crease_angle(std::optional<double> degrees, std::string& error)
  {
    if (degrees && !(*degrees > 0 && *degrees < 180)) {
      error = "the crease angle must lie strictly between 0 and 180 degrees";
      return false;
    }
    if (job_running()) {
      error = "a computation is running";
      return false;
    }
    crease_angle_ = degrees;
    if (!has_mesh()) // kept for the mesh to come
      return true;
    update_creases();
    rebuild_sweeper();
    update_normals();
    update_lines();
    return true;
  }
  const std::optional<double>& crease_angle() const { return crease_angle_; }
  std::size_t number_of_crease_edges() const { return number_of_crease_edges_; }

  // The highlight lines as polylines (a closed line repeats its first point), in the model's
  // canonical order: traced from the model on the first call after a change (the lines drawn
  // are the segments below, which need no tracing).
  const Polylines& lines() const
  {
    trace_lines();
    return lines_;
  }
  std::size_t number_of_lines() const { return lines().size(); }
  // The segments of the lines, ready for drawing: pairs of indices into line_points() (which
  // may hold points no segment uses), in no particular order; the same segments, point for
  // point, as those of lines() (Highlight_line_sweeper::compute_segments()).
  const std::vector<Point>& line_points() const { return line_points_; }
  const Segments& line_segments() const { return line_segments_; }
  // The indices of the lights whose lines are computed.
  const std::pair<long long, long long>& levels() const { return levels_; }
  // Time of the latest light or mesh change to new lines ready for drawing, in milliseconds.
  double update_milliseconds() const { return update_milliseconds_; }
  // The highlight distance value d (eq. 1) of each shading point, for the zebra; NaN where the
  // normal is parallel to the light plane or, the lines being those of the facing side only,
  // turned away from it.
  // Empty unless asked for with show_distance_field(true).
  const std::vector<double>& distances() const { return distances_; }
  void show_distance_field(bool shown)
  {
    if (shown == distance_field_wanted_)
      return;
    distance_field_wanted_ = shown;
    if (shown && has_mesh()) {
      update_distances();
      ++revision_;
    }
  }

  // ---- The region -----------------------------------------------------------------------------

  void set_region(std::vector<Face> faces)
  {
    region_ = std::move(faces);
    update_region_decorations();
    ++revision_;
  }
  void clear_region() { set_region({}); }
  const std::vector<Face>& region() const { return region_; }
  const std::vector<Vertex>& movable_vertices() const { return movable_; }
  const Polylines& desired_lines() const { return desired_; }
  const std::string& region_note() const { return region_note_; }

  // ---- Detection ------------------------------------------------------------------------------

  const std::vector<HL::Highlight_line_irregularity<Mesh>>& detected() const { return detected_; }
  // Sweeps the lights over the whole mesh from all sides in the worker thread.
  void start_detection()
  {
    if (job_running())
      return;
    job_kind_ = Job_kind::DETECTION;
    detection_fraction_ = 0;
    auto copy = std::make_shared<Mesh>(*mesh_);
    // Denser lights than shown, as the example programs sweep them: a defect is found only
    // where several lines cross it.
    const Lights lights = HL::default_light_setup(*mesh_, HLP::number_of_lines(60));
    job_.start([this, copy, lights] {
      std::vector<HL::Highlight_line_irregularity<Mesh>> found;
      try {
        CGAL::detect_highlight_line_irregularities<CGAL::Parallel_if_available_tag>(
            *copy, lights, std::back_inserter(found), CGAL::parameters::callback([this](double f) {
              detection_fraction_ = f;
              return !job_.cancel_requested();
            }));
      } catch (const std::exception& e) {
        std::lock_guard<std::mutex> lock(mutex_);
        job_error_ = e.what();
      }
      std::lock_guard<std::mutex> lock(mutex_);
      detection_result_ = std::move(found);
    });
  }
  double detection_fraction() const { return detection_fraction_; }

  // ---- Fairing --------------------------------------------------------------------------------

  // Fairs the region with the current lights in the worker thread; the window shows each
  // iteration as it comes (poll()).
  bool start_fairing(unsigned int iterations, std::string& error)
  {
    if (job_running()) {
      error = "a computation is running";
      return false;
    }
    if (region_.empty()) {
      error = "no region: pick one first";
      return false;
    }
    job_kind_ = Job_kind::FAIRING;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      progress_ = Fairing_progress();
      fairing_report_.reset();
      job_error_.clear();
    }
    auto copy = std::make_shared<Mesh>(*mesh_);
    const std::vector<Face> region = region_;
    const Lights lights = *lights_;
    job_.start([this, copy, region, lights, iterations] {
      // The visitor runs between two iterations, when the copy is a consistent iterate.
      auto visitor = [this, copy](const HL::Fairing_report::Iteration& iteration) {
        std::lock_guard<std::mutex> lock(mutex_);
        progress_.iterations.push_back(iteration);
        progress_.positions = positions_of(*copy);
        progress_.new_positions = true;
        return !job_.cancel_requested();
      };
      try {
        HL::Fairing_report report = CGAL::fair_with_highlight_lines(
            *copy, region, lights,
            HLP::combine(CGAL::parameters::number_of_iterations(iterations),
                         HLP::fairing_visitor(visitor)));
        std::lock_guard<std::mutex> lock(mutex_);
        fairing_report_ = report;
        progress_.positions = positions_of(*copy);
        progress_.new_positions = true;
      } catch (const std::exception& e) {
        std::lock_guard<std::mutex> lock(mutex_);
        job_error_ = e.what();
      }
    });
    return true;
  }
  // Until poll() has taken over the result: a script waits for that, not just for the worker.
  bool job_running() const { return job_kind_ != Job_kind::NONE; }
  bool fairing_running() const { return job_kind_ == Job_kind::FAIRING; }
  bool detection_running() const { return job_kind_ == Job_kind::DETECTION; }
  // Cancels the running job: a cancelled fairing leaves the mesh as it was before it.
  void cancel() { job_.request_cancel(); }
  // Called once per frame by the window: takes over what the worker produced. Returns a message
  // when a job ended (empty otherwise).
  std::string poll()
  {
    std::string message;
    // Whether the worker had finished is decided first: then the positions taken below are its
    // last ones (the fairing's result, which may be an earlier iterate than the last shown).
    const bool done = job_.finished();
    if (done)
      job_.wait();
    if (job_kind_ == Job_kind::FAIRING) {
      std::vector<Point> positions;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (progress_.new_positions) {
          positions = progress_.positions;
          progress_.new_positions = false;
        }
        shown_iterations_ = progress_.iterations;
      }
      if (!positions.empty() && !job_.cancel_requested())
        set_positions(positions);
    }
    if (!done)
      return message;
    std::lock_guard<std::mutex> lock(mutex_);
    if (job_kind_ == Job_kind::FAIRING) {
      if (job_.cancel_requested() || !job_error_.empty()) {
        set_positions(history_[history_index_]);
        message = job_error_.empty() ? "fairing cancelled, mesh restored"
                                     : "fairing failed: " + job_error_;
      } else {
        push_history();
        message = std::string("fairing: ") + HL::to_string(fairing_report_->status) + " after " +
                  std::to_string(fairing_report_->iterations) + " iterations";
      }
    } else if (job_kind_ == Job_kind::DETECTION) {
      if (job_.cancel_requested())
        message = "detection cancelled";
      else if (!job_error_.empty())
        message = "detection failed: " + job_error_;
      else {
        detected_ = std::move(detection_result_);
        ++revision_;
        message = "detection: " + std::to_string(detected_.size()) + " irregular region(s)";
      }
    }
    job_error_.clear();
    job_kind_ = Job_kind::NONE;
    return message;
  }
  const std::vector<HL::Fairing_report::Iteration>& fairing_iterations() const
  {
    return shown_iterations_;
  }
  const std::optional<HL::Fairing_report>& fairing_report() const { return fairing_report_; }

  // ---- Undo, redo, before / after ------------------------------------------------------------

  bool can_undo() const { return history_index_ > 0 && !job_running(); }
  bool can_redo() const { return history_index_ + 1 < history_.size() && !job_running(); }
  void undo()
  {
    if (can_undo())
      set_positions(history_[--history_index_]);
  }
  void redo()
  {
    if (can_redo())
      set_positions(history_[++history_index_]);
  }
  // Shows the mesh before the latest change (true) or as it is (false).
  void show_before(bool before)
  {
    if (history_index_ == 0 || job_running())
      return;
    set_positions(history_[before ? history_index_ - 1 : history_index_]);
  }

  // Presses a smooth dent (1 - (r/R)^2)^3 of the given depth into the surface around `center`,
  // along the normals, as the example fair_with_highlight_lines does: something to find and
  // fair on a clean mesh. Undoable.
  void press_dent(const Point& center, double radius, double depth)
  {
    if (job_running() || !(radius > 0))
      return;
    std::vector<Point> moved = positions();
    for (Vertex v : vertices(*mesh_)) {
      const double r2 = CGAL::squared_distance(mesh_->point(v), center) / (radius * radius);
      if (r2 >= 1)
        continue;
      const std::size_t i = std::size_t(v);
      const Vector n(normals_[3 * i], normals_[3 * i + 1], normals_[3 * i + 2]);
      moved[i] = mesh_->point(v) - depth * (1 - r2) * (1 - r2) * (1 - r2) * n;
    }
    set_positions(moved);
    push_history();
  }

  // ---- Files ----------------------------------------------------------------------------------

  bool save_mesh(const std::string& path) const { return mesh_io::write_mesh(path, *mesh_); }
  // Where "save" writes by default: next to the input, in its format.
  std::string default_save_path() const
  {
    const std::string ext = mesh_io::extension(path_);
    const std::string stem = path_.substr(0, path_.size() - ext.size());
    return stem + "_edited" + mesh_io::output_extension(path_);
  }
  bool save_lines(const std::string& path) const { return write_polylines(path, lines()); }
  bool save_region(const std::string& path) const { return write_face_ids(path, region_); }
  bool save_lights(const std::string& path) const { return write_lights(path, *lights_, levels_); }

private:
  enum class Job_kind { NONE, FAIRING, DETECTION };

  // The sweeper keeps a reference to the mesh: the mesh lives at a fixed address.
  const Mesh& mesh_storage(Mesh&& mesh)
  {
    sweeper_.reset();
    mesh_ = std::make_unique<Mesh>(std::move(mesh));
    return *mesh_;
  }

  // Vertex positions by vertex index (the meshes read have no removed vertex).
  static std::vector<Point> positions_of(const Mesh& mesh)
  {
    std::vector<Point> result;
    result.reserve(num_vertices(mesh));
    for (Vertex v : vertices(mesh))
      result.push_back(mesh.point(v));
    return result;
  }
  std::vector<Point> positions() const { return positions_of(*mesh_); }
  void set_positions(const std::vector<Point>& positions)
  {
    for (Vertex v : vertices(*mesh_))
      mesh_->point(v) = positions[std::size_t(v)];
    // The sweeper reads the creases when it is built: a new one only if they changed with the
    // positions (the normals of its sectors follow the positions like the others).
    if (crease_angle_ && update_creases())
      rebuild_sweeper();
    else
      sweeper_->update_positions();
    ++positions_revision_;
    update_normals();
    update_lines();
    update_region_decorations();
  }
  void push_history()
  {
    history_.resize(history_index_ + 1);
    history_.push_back(positions());
    ++history_index_;
  }

  void compute_bounding_box()
  {
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(*mesh_);
    box_center_ = {(box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2,
                   (box.zmin() + box.zmax()) / 2};
    box_diagonal_ =
        std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                  CGAL::square(box.zmax() - box.zmin()));
  }

  void update_normals()
  {
    normals_.assign(3 * num_vertices(*mesh_), 0.0);
    for (Face f : faces(*mesh_)) {
      const auto h = mesh_->halfedge(f);
      const Vertex a = mesh_->source(h), b = mesh_->target(h), c = mesh_->target(mesh_->next(h));
      const Vector n =
          CGAL::cross_product(mesh_->point(b) - mesh_->point(a), mesh_->point(c) - mesh_->point(a));
      for (Vertex v : {a, b, c})
        for (int k = 0; k < 3; ++k)
          normals_[3 * std::size_t(v) + std::size_t(k)] += n[k];
    }
    normalize_triples(normals_);
    sector_normals_.clear();
    if (cut_.origin.empty())
      return;
    sector_normals_.assign(3 * cut_.origin.size(), 0.0);
    for (Face f : faces(*mesh_)) {
      const auto h = mesh_->halfedge(f);
      const Vertex a = mesh_->source(h), b = mesh_->target(h), c = mesh_->target(mesh_->next(h));
      const Vector n =
          CGAL::cross_product(mesh_->point(b) - mesh_->point(a), mesh_->point(c) - mesh_->point(a));
      for (Halfedge corner : CGAL::halfedges_around_face(h, *mesh_))
        for (int k = 0; k < 3; ++k)
          sector_normals_[3 * cut_.point_of_corner[std::size_t(corner)] + std::size_t(k)] += n[k];
    }
    normalize_triples(sector_normals_);
  }
  static void normalize_triples(std::vector<double>& v)
  {
    for (std::size_t i = 0; i < v.size(); i += 3) {
      const double length = std::sqrt(v[i] * v[i] + v[i + 1] * v[i + 1] + v[i + 2] * v[i + 2]);
      for (std::size_t k = 0; k < 3; ++k)
        v[i + k] = length > 0 ? v[i + k] / length : 0;
    }
  }

  // The lines shown: those of the visible levels, on the side of the surface facing the lights.
  auto lines_parameters() const
  {
    return HLP::combine(HLP::level_range(levels_), HLP::facing_side_only(true));
  }

  // The creases at the angle asked for (none without one); true if they changed.
  bool update_creases()
  {
    std::vector<Edge> before, after;
    for (Edge e : edges(*mesh_))
      if (creases_[e]) {
        before.push_back(e);
        creases_[e] = false;
      }
    if (crease_angle_) {
      CGAL::Polygon_mesh_processing::detect_sharp_edges(*mesh_, *crease_angle_, creases_);
      for (Edge e : edges(*mesh_))
        if (creases_[e])
          after.push_back(e);
    }
    number_of_crease_edges_ = after.size();
    const bool changed = before != after;
    if (changed || crease_angle_.has_value() == cut_.origin.empty()) {
      cut_ =
          crease_angle_ ? mesh_picture::cut_corners(*mesh_, creases_) : mesh_picture::Cut_corners();
      ++shading_generation_;
    }
    return changed;
  }
  // A sweeper that cuts the mesh along the creases if asked for, else the paper's.
  void rebuild_sweeper()
  {
    sweeper_.reset();
    sweeper_ = crease_angle_ ? std::make_unique<Sweeper>(*mesh_, HLP::crease_edge_map(creases_))
                             : std::make_unique<Sweeper>(*mesh_);
  }

  // New lights or a moved mesh: the lights that fall on the surface, the lines through the
  // sweeper (its normals are cached; after set_positions() they were updated once) and, if the
  // zebra is shown, the distance field.
  void update_lines()
  {
    const auto start = std::chrono::steady_clock::now();
    lights_ = controls_.applied_to(*reference_lights_);
    levels_ = visible_levels();
    // The segments only: the polylines are traced when asked for (lines()). Into the arrays of
    // the previous update: their memory is reused.
    sweeper_->compute_segments(*lights_, line_points_, line_segments_, lines_parameters());
    lines_traced_ = false;
    if (distance_field_wanted_)
      update_distances();
    else
      distances_.clear();
    update_milliseconds_ =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    ++revision_;
  }

  // The polylines of the current lights, from the model (into the model of the previous
  // tracing, and into the polylines: their memory is reused).
  void trace_lines() const
  {
    if (lines_traced_)
      return;
    lines_traced_ = true;
    if (!sweeper_ || !lights_) {
      lines_.clear();
      return;
    }
    sweeper_->compute(*lights_, model_, lines_parameters());
    const auto& nodes = model_.nodes();
    lines_.resize(model_.lines().size());
    for (std::size_t i = 0; i < lines_.size(); ++i) {
      const auto& line = model_.lines()[i];
      std::vector<Point>& polyline = lines_[i];
      polyline.clear();
      for (std::size_t n : line.nodes)
        polyline.push_back(nodes[n].point);
      if (line.is_closed && !line.nodes.empty())
        polyline.push_back(nodes[line.nodes.front()].point);
    }
  }

  // d = ((P - A0) x H)·N / (Z·N) (eq. 1) of vertex i, on the side facing the lights; NaN elsewhere.
  double distance(std::size_t i, const Lights& lights) const
  {
    return distance(mesh_->point(Vertex(Mesh::size_type(i))), &normals_[3 * i], lights);
  }
  double distance(const Point& p, const double* n, const Lights& lights) const
  {
    const std::array<double, 3>& a = lights.base_point_array();
    const std::array<double, 3>& h = lights.light_direction_array();
    const std::array<double, 3>& z = lights.plane_normal_array();
    const double zn = z[0] * n[0] + z[1] * n[1] + z[2] * n[2];
    if (!(zn > 1e-12))
      return std::numeric_limits<double>::quiet_NaN();
    const double w[3] = {p.x() - a[0], p.y() - a[1], p.z() - a[2]};
    const double wxh[3] = {w[1] * h[2] - w[2] * h[1], w[2] * h[0] - w[0] * h[2],
                           w[0] * h[1] - w[1] * h[0]};
    return (wxh[0] * n[0] + wxh[1] * n[1] + wxh[2] * n[2]) / zn;
  }

  void update_distances()
  {
    const std::vector<double>& normals = shading_normals();
    distances_.resize(number_of_shading_points());
    for (std::size_t i = 0; i < distances_.size(); ++i)
      distances_[i] = distance(mesh_->point(shading_origin(i)), &normals[3 * i], *lights_);
  }

  // The lights whose lines a light tunnel shows: those between the 5 % and 95 % quantiles of d (as
  // default_level_range() takes them), estimated on at most 2^16 vertices spread over the mesh.
  // All lights would also image the lights far out in the plane on the surface parts almost
  // parallel to it, thousands of short lines bunched at the silhouettes (as does a real
  // reflection, but they hide the surface and cost most of the time).
  // Moving the lights across by u = offset·s (along I = H x Z) changes every d by -u (W x H
  // loses u I x H = u Z, and Z·N / Z·N = 1) and keeps their order: the quantiles are taken once
  // per direction, tilt and mesh position, for the lights without offset, and shifted.
  std::pair<long long, long long> visible_levels()
  {
    Quantiles& q = quantiles_;
    if (!q.valid || q.angle_degrees != controls_.angle_degrees ||
        q.tilt_degrees != controls_.tilt_degrees || q.positions_revision != positions_revision_) {
      Light_controls unmoved = controls_;
      unmoved.offset = 0;
      const Lights lights = unmoved.applied_to(*reference_lights_);
      const std::size_t n = num_vertices(*mesh_);
      const std::size_t stride = (std::max)(n >> 16, std::size_t(1));
      std::vector<double>& finite = q.samples;
      finite.clear();
      for (std::size_t i = 0; i < n; i += stride) {
        const double d = distance(i, lights);
        if (std::isfinite(d))
          finite.push_back(d);
      }
      const auto quantile = [&](double f) {
        auto at = finite.begin() + std::ptrdiff_t(f * double(finite.size() - 1));
        std::nth_element(finite.begin(), at, finite.end());
        return *at;
      };
      q.valid = true;
      q.angle_degrees = controls_.angle_degrees;
      q.tilt_degrees = controls_.tilt_degrees;
      q.positions_revision = positions_revision_;
      q.none = finite.empty();
      if (!q.none) {
        q.low = quantile(0.05);
        q.high = quantile(0.95);
      }
    }
    if (q.none)
      return {0, 0};
    const double s = lights_->spacing_value();
    return {(long long)std::floor(std::max(q.low / s - controls_.offset, -1e6)),
            (long long)std::ceil(std::min(q.high / s - controls_.offset, 1e6))};
  }

  void update_region_decorations()
  {
    movable_.clear();
    desired_.clear();
    region_note_.clear();
    if (region_.empty())
      return;
    try {
      HL::movable_vertices(*mesh_, region_, std::back_inserter(movable_));
      HL::desired_highlight_lines(*mesh_, region_, *lights_, std::back_inserter(desired_));
    } catch (const HL::Invalid_input& e) {
      region_note_ = e.what();
    }
  }

  std::size_t revision_ = 0, mesh_generation_ = 0, positions_revision_ = 0;
  std::unique_ptr<Mesh> mesh_;
  std::unique_ptr<Sweeper> sweeper_;
  // The latest lines: their segments, and the model and polylines traced from them on demand.
  std::vector<Point> line_points_;
  Segments line_segments_;
  mutable Sweeper::Model model_;
  mutable Polylines lines_;
  mutable bool lines_traced_ = false;
  std::string path_;
  std::array<double, 3> box_center_{};
  double box_diagonal_ = 1;
  std::vector<double> normals_, distances_;
  // The shading points of the mesh cut along the creases (empty without creases), and their
  // normals.
  mesh_picture::Cut_corners cut_;
  std::vector<double> sector_normals_;
  std::size_t shading_generation_ = 0;
  bool distance_field_wanted_ = false;
  // The crease edges of the cut model, if one is asked for.
  Mesh::Property_map<Edge, bool> creases_;
  std::optional<double> crease_angle_;
  std::size_t number_of_crease_edges_ = 0;

  std::optional<Lights> reference_lights_, lights_;
  Light_controls controls_;
  std::pair<long long, long long> levels_{0, -1};
  // The quantiles of d of visible_levels() for the lights without their offset.
  struct Quantiles
  {
    bool valid = false, none = true;
    double angle_degrees = 0, tilt_degrees = 0;
    std::size_t positions_revision = 0;
    double low = 0, high = 0;
    std::vector<double> samples;
  } quantiles_;
  double update_milliseconds_ = 0;

  std::vector<Face> region_;
  std::vector<Vertex> movable_;
  Polylines desired_;
  std::string region_note_;
  std::vector<HL::Highlight_line_irregularity<Mesh>> detected_;

  std::vector<std::vector<Point>> history_;
  std::size_t history_index_ = 0;

  Background_job job_;
  Job_kind job_kind_ = Job_kind::NONE;
  std::mutex mutex_;
  Fairing_progress progress_;
  std::vector<HL::Fairing_report::Iteration> shown_iterations_;
  std::optional<HL::Fairing_report> fairing_report_;
  std::vector<HL::Highlight_line_irregularity<Mesh>> detection_result_;
  std::atomic<double> detection_fraction_{0};
  std::string job_error_;
};

} // namespace viewer

#endif // HIGHLIGHT_LINES_DEMO_VIEWER_SESSION_H
