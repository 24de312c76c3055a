// The interactive demo: a triangle mesh with its highlight lines, the lights swept by hand, a
// region picked with the mouse and faired while the window keeps drawing.
//
//   highlight_lines_viewer [MESH] [--script FILE] [--size W H]
//
// GLFW opens the window, Dear ImGui draws the panel, and the mesh and lines are drawn with
// OpenGL 1.x client arrays (fixed-function lighting, a 1D texture for the zebra stripes): it
// runs on any driver, Mesa's software llvmpipe under Xvfb included. --script replays actions
// (see `usage`) in the window, one per frame, so that its screenshots are what a user sees.
#include "viewer_session.h"

#include <CGAL/Highlight_lines/internal/vector3.h>

#include "highlight_picture.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl2.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace viewer;

const char* usage =
    "usage: highlight_lines_viewer [MESH] [--crease-angle DEG] [--script FILE] [--size W H]\n"
    "\n"
    "Shows a triangle mesh (OFF, OBJ, PLY or STL; default: the bundled VW Beetle body) with\n"
    "its highlight lines under a row of tube lights placed above it.\n"
    "\n"
    "mouse: left drag orbit, right drag pan, wheel zoom, shift+left click pick a region,\n"
    "       ctrl+left drag move the lights across (x) and tilt them (y), ctrl+right drag turn "
    "them\n"
    "keys:  left/right move the lights across, a/d turn them, w/s tilt them, up/down spacing,\n"
    "       z zebra, l lines, c creases, f fair the region, escape cancel, ctrl+z undo,\n"
    "       ctrl+y redo\n"
    "\n"
    "--crease-angle DEG cuts the model along the creases: the edges whose faces' normals\n"
    "differ by more than DEG degrees (Polygon_mesh_processing::detect_sharp_edges()), so that\n"
    "the lines of a CAD part run straight on its flat faces and end at its creases (key c\n"
    "toggles it, at 45 degrees unless given; the shading and the zebra are cut there too).\n"
    "\n"
    "--script FILE runs these actions, one per line and one per frame (# starts a comment):\n"
    "  load PATH                  read a mesh\n"
    "  lights angle DEG           turn the light direction in the light plane (from the start)\n"
    "  lights direction X Y Z     the light direction (projected into the light plane)\n"
    "  lights tilt DEG            tilt the light plane about the light direction\n"
    "  lights offset D            move the lights across by D spacings (from the start)\n"
    "  lights spacing S           the distance between lights\n"
    "  sweep STEPS DELTA          move the lights across by DELTA spacings, STEPS times, a frame\n"
    "                             each\n"
    "  camera AZIMUTH ELEVATION ZOOM  view direction in degrees, zoom (1: whole mesh)\n"
    "  frames N                   draw N frames, print their mean time\n"
    "  zebra on|off, lines on|off the zebra stripes of the same distance field; the lines\n"
    "  creases DEG|off            cut the model along the creases sharper than DEG degrees\n"
    "  pick X Y                   pick the face under pixel (X, Y) (from the top left)\n"
    "  pick_face ID               pick face ID (at its centroid)\n"
    "  grow RADIUS                the region: faces around the picked point within RADIUS\n"
    "  dent [DEPTH]               press a dent (depth in diagonals, default 0.006) at the picked\n"
    "                             point, 0.6 times the region's radius wide (undoable)\n"
    "  detect                     find irregular regions (waits until done)\n"
    "  select_detected I          the region: detected region I (0: the likeliest defect)\n"
    "  fair [ITERATIONS]          fair the region (waits until done; default 50 iterations)\n"
    "  undo, redo                 the mesh before / after the latest fairing (or dent)\n"
    "  before on|off              show the mesh before the latest change / as it is\n"
    "  save PATH, save_lines PATH, save_region PATH, save_lights PATH, screenshot PATH.png\n"
    "  quit\n"
    "At the end of the script the window stays open for the user (unless it quits); a failing\n"
    "action closes it with exit status 1.\n";

// ---- Camera -----------------------------------------------------------------------------------

// The package's 3-vector and its operations.
using namespace CGAL::Highlight_lines::internal::vector3;
Vec3 normalized(const Vec3& a)
{
  return (1 / norm(a)) * a;
}
Vec3 to_vec3(const Vector& v)
{
  return {v.x(), v.y(), v.z()};
}

// An orbit camera around the mesh: "up" is the light plane's normal of the light tunnel placed
// over the mesh (the height of a car body), azimuth 0 looks along the lights.
struct Camera
{
  Vec3 up{0, 1, 0}, forward_axis{0, 0, 1}, side_axis{1, 0, 0};
  Vec3 target{0, 0, 0};
  double radius = 1; // of the mesh
  double azimuth = 35, elevation = 30, zoom = 1;
  double field_of_view = 30; // vertical, degrees
  int width = 1, height = 1;
  // The target is drawn this many pixels right of the window's centre: in the middle of the
  // part the panel leaves free.
  double shift = 0;
  double shift_ndc() const { return 2 * shift / std::max(width, 1); }

  void frame(const Session& session)
  {
    up = to_vec3(session.reference_lights().plane_normal());
    forward_axis = to_vec3(session.reference_lights().light_direction());
    side_axis = cross(up, forward_axis);
    target = session.box_center();
    radius = session.box_diagonal() / 2;
  }
  double distance() const { return radius / std::sin(field_of_view * M_PI / 360) / zoom * 1.05; }
  // From the target towards the eye.
  Vec3 back() const
  {
    const double a = azimuth * M_PI / 180, e = elevation * M_PI / 180;
    return std::cos(e) * std::cos(a) * forward_axis + std::cos(e) * std::sin(a) * side_axis +
           std::sin(e) * up;
  }
  Vec3 eye() const { return target + distance() * back(); }
  Vec3 right() const { return normalized(cross(-1 * back(), up)); }
  Vec3 camera_up() const { return cross(right(), -1 * back()); }
  double near_plane() const { return std::max(distance() - 1.5 * radius, distance() * 0.01); }
  double far_plane() const { return distance() + 1.5 * radius; }

  void load_matrices() const
  {
    const double aspect = double(width) / double(std::max(height, 1));
    const double f = 1 / std::tan(field_of_view * M_PI / 360);
    const double n = near_plane(), fa = far_plane();
    const double projection[16] = {f / aspect,
                                   0,
                                   0,
                                   0,
                                   0,
                                   f,
                                   0,
                                   0,
                                   -shift_ndc(),
                                   0,
                                   (fa + n) / (n - fa),
                                   -1,
                                   0,
                                   0,
                                   2 * fa * n / (n - fa),
                                   0};
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixd(projection);
    const Vec3 r = right(), u = camera_up(), b = back(), e = eye();
    const double view[16] = {r[0], u[0], b[0], 0, r[1],       u[1],       b[1],       0,
                             r[2], u[2], b[2], 0, -dot(r, e), -dot(u, e), -dot(b, e), 1};
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixd(view);
  }
  // The ray through the centre of pixel (x, y), counted from the top left.
  Ray ray_through(double x, double y) const
  {
    const double t = std::tan(field_of_view * M_PI / 360);
    const double aspect = double(width) / double(std::max(height, 1));
    const double sx = (2 * (x + 0.5) / width - 1 - shift_ndc()) * t * aspect;
    const double sy = (1 - 2 * (y + 0.5) / height) * t;
    return {eye(), normalized(-1 * back() + sx * right() + sy * camera_up())};
  }
  void pan(double dx_pixels, double dy_pixels)
  {
    const double per_pixel = 2 * distance() * std::tan(field_of_view * M_PI / 360) / height;
    target = target - (dx_pixels * per_pixel) * right() + (dy_pixels * per_pixel) * camera_up();
  }
};

// ---- Drawing ----------------------------------------------------------------------------------

// The session's geometry as flat float arrays for glDrawElements, rebuilt when it changes: the
// positions and normals only when the mesh moves or its shading points change (not when the
// lights do), the stripes only while the zebra is shown. The surface is drawn on the session's
// shading points (the vertices, or the mesh cut along the creases).
struct Draw_arrays
{
  std::size_t revision = std::size_t(-1), mesh_generation = std::size_t(-1),
              positions_revision = std::size_t(-1), shading_generation = std::size_t(-1);
  std::vector<float> positions, normals, stripes;
  std::vector<unsigned int> triangles, region_triangles;
  std::vector<std::vector<unsigned int>> detected_triangles;
  std::vector<bool> detected_is_local; // a dent or a bump, not an elongated or extended region
  std::vector<float> line_points;      // drawn as GL_LINES by the session's line_segments()
  std::vector<std::vector<float>> desired;
  std::vector<float> movable;

  void update(const Session& s)
  {
    if (revision == s.revision())
      return;
    revision = s.revision();
    const Mesh& mesh = s.mesh();
    const bool new_shading_points =
        mesh_generation != s.mesh_generation() || shading_generation != s.shading_generation();
    if (positions_revision != s.positions_revision() || new_shading_points) {
      positions_revision = s.positions_revision();
      positions.clear();
      for (std::size_t i = 0; i < s.number_of_shading_points(); ++i) {
        const Point& p = mesh.point(s.shading_origin(i));
        positions.insert(positions.end(), {float(p.x()), float(p.y()), float(p.z())});
      }
      normals.assign(s.shading_normals().begin(), s.shading_normals().end());
    }
    stripes.clear();
    if (!s.distances().empty()) {
      const double spacing = CGAL::to_double(s.lights().spacing());
      stripes.reserve(s.distances().size());
      for (double d : s.distances())
        // A line (d = m s) runs in the middle of a dark stripe: dark where frac(d/s + 1/4) < 1/2.
        stripes.push_back(std::isfinite(d) ? float(std::fmod(d / spacing + 0.25, 64.0)) : 0.75f);
    }
    auto face_corners = [&](Face f, std::vector<unsigned int>& out) {
      for (Mesh::Halfedge_index h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
        out.push_back((unsigned int)(s.shading_point(h)));
    };
    if (new_shading_points) {
      mesh_generation = s.mesh_generation();
      shading_generation = s.shading_generation();
      triangles.clear();
      for (Face f : faces(mesh))
        face_corners(f, triangles);
    }
    region_triangles.clear();
    for (Face f : s.region())
      face_corners(f, region_triangles);
    detected_triangles.clear();
    detected_is_local.clear();
    for (const auto& found : s.detected()) {
      detected_is_local.push_back(found.kind == HL::Irregularity_kind::DENT ||
                                  found.kind == HL::Irregularity_kind::BUMP);
      detected_triangles.emplace_back();
      for (Face f : found.faces)
        face_corners(f, detected_triangles.back());
    }
    auto flatten = [](const Polylines& polylines, std::vector<std::vector<float>>& out) {
      out.clear();
      for (const auto& polyline : polylines) {
        out.emplace_back();
        for (const Point& p : polyline)
          out.back().insert(out.back().end(), {float(p.x()), float(p.y()), float(p.z())});
      }
    };
    line_points.resize(3 * s.line_points().size());
    for (std::size_t i = 0; i < s.line_points().size(); ++i) {
      const Point& p = s.line_points()[i];
      line_points[3 * i] = float(p.x());
      line_points[3 * i + 1] = float(p.y());
      line_points[3 * i + 2] = float(p.z());
    }
    flatten(s.desired_lines(), desired);
    movable.clear();
    for (Vertex v : s.movable_vertices()) {
      const Point& p = mesh.point(v);
      movable.insert(movable.end(), {float(p.x()), float(p.y()), float(p.z())});
    }
  }
};

struct View_options
{
  bool zebra = false;
  bool show_lines = true;
  bool show_detected = true;
};

GLuint make_stripe_texture()
{
  unsigned char texels[64];
  for (int i = 0; i < 64; ++i)
    texels[i] = i < 32 ? 25 : 245;
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_1D, texture);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_LUMINANCE, 64, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, texels);
  return texture;
}

void draw_polylines(const std::vector<std::vector<float>>& polylines)
{
  for (const auto& polyline : polylines) {
    glVertexPointer(3, GL_FLOAT, 0, polyline.data());
    glDrawArrays(GL_LINE_STRIP, 0, GLsizei(polyline.size() / 3));
  }
}

void draw_scene(const Session& session, const Draw_arrays& arrays, const Camera& camera,
                const View_options& options, GLuint stripe_texture)
{
  glViewport(0, 0, camera.width, camera.height);
  glClearColor(0.93f, 0.94f, 0.96f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (!session.has_mesh())
    return;
  camera.load_matrices();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glEnableClientState(GL_VERTEX_ARRAY);

  // The surface, lit from the eye, pushed back so that lines on it win the depth test.
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1, 1);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glPushMatrix();
  glLoadIdentity();
  const float eye_light[4] = {0.3f, 0.5f, 1, 0};
  glLightfv(GL_LIGHT0, GL_POSITION, eye_light);
  glPopMatrix();
  const float ambient[4] = {0.25f, 0.25f, 0.27f, 1}, white[4] = {1, 1, 1, 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glEnable(GL_NORMALIZE);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, arrays.positions.data());
  glNormalPointer(GL_FLOAT, 0, arrays.normals.data());
  if (options.zebra && !arrays.stripes.empty()) {
    glEnable(GL_TEXTURE_1D);
    glBindTexture(GL_TEXTURE_1D, stripe_texture);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(1, GL_FLOAT, 0, arrays.stripes.data());
    glColor3f(1, 1, 1);
  } else {
    glColor3f(0.62f, 0.67f, 0.74f);
  }
  glDrawElements(GL_TRIANGLES, GLsizei(arrays.triangles.size()), GL_UNSIGNED_INT,
                 arrays.triangles.data());
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glDisable(GL_TEXTURE_1D);

  // Regions, tinted over the surface.
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  if (options.show_detected)
    for (std::size_t i = 0; i < arrays.detected_triangles.size(); ++i) {
      if (arrays.detected_is_local[i])
        glColor4f(0.9f, 0.25f, 0.15f, 0.5f);
      else
        glColor4f(0.95f, 0.7f, 0.35f, 0.3f);
      glDrawElements(GL_TRIANGLES, GLsizei(arrays.detected_triangles[i].size()), GL_UNSIGNED_INT,
                     arrays.detected_triangles[i].data());
    }
  glColor4f(0.3f, 0.6f, 0.95f, 0.5f);
  glDrawElements(GL_TRIANGLES, GLsizei(arrays.region_triangles.size()), GL_UNSIGNED_INT,
                 arrays.region_triangles.data());
  glDepthMask(GL_TRUE);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisable(GL_LIGHTING);
  glDisable(GL_POLYGON_OFFSET_FILL);

  // Lines over the surface.
  glEnable(GL_LINE_SMOOTH);
  if (options.show_lines) {
    glLineWidth(1.2f);
    if (options.zebra)
      glColor3f(0.85f, 0.1f, 0.1f);
    else
      glColor3f(0.08f, 0.09f, 0.15f);
    const Segments& segments = session.line_segments();
    static_assert(sizeof(Segments::value_type) == 2 * sizeof(GLuint), "segments as GLuint pairs");
    glVertexPointer(3, GL_FLOAT, 0, arrays.line_points.data());
    glDrawElements(GL_LINES, GLsizei(2 * segments.size()), GL_UNSIGNED_INT, segments.data());
  }
  glPointSize(3);
  glColor3f(0.1f, 0.6f, 0.25f);
  glVertexPointer(3, GL_FLOAT, 0, arrays.movable.data());
  glDrawArrays(GL_POINTS, 0, GLsizei(arrays.movable.size() / 3));
  glLineWidth(3);
  glColor3f(0.1f, 0.3f, 0.95f);
  draw_polylines(arrays.desired);
  glDisable(GL_LINE_SMOOTH);
  glDisable(GL_BLEND);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisable(GL_DEPTH_TEST);
}

// The back buffer as the user sees it, written with the command-line programs' PNG writer
// (highlight_picture.h).
bool write_screenshot(const std::string& path, int width, int height)
{
  std::vector<unsigned char> rgb(std::size_t(width) * std::size_t(height) * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  highlight_picture::Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const unsigned char* p = &rgb[(std::size_t(height - 1 - y) * std::size_t(width) + x) * 3];
      image(x, y) = {p[0], p[1], p[2]};
    }
  return highlight_picture::write_png(path, image);
}

// ---- The application --------------------------------------------------------------------------

struct App
{
  Session session;
  Camera camera;
  View_options view;
  Draw_arrays arrays;
  GLFWwindow* window = nullptr;
  GLuint stripe_texture = 0;

  // The picked point, from which the region grows.
  std::optional<std::pair<Face, Point>> picked;
  double region_radius = 0;
  int fairing_iterations = 50;
  double crease_angle = 45; // of the cut model, when key c or the panel turns it on
  float crease_slider = 45;
  bool crease_slider_held = false;
  bool showing_before = false;
  int panel_width = 330;
  int frames = 0;
  int timed_frames = 0, timed_frame_count = 1; // the frames action
  std::chrono::steady_clock::time_point timed_start;
  std::size_t reported_iterations = 0;
  std::string status;
  char path_field[1024] = "";
  char save_field[1024] = "";

  // Script state.
  std::deque<std::pair<int, std::string>> script; // line number, action
  bool scripted = false;
  bool script_failed = false;
  std::string pending_screenshot;

  // Mouse state.
  double last_x = 0, last_y = 0;
  int dragged_button = -1; // the button held since a press on the view, or -1
  bool pick_requested = false;
  double scroll = 0;
  std::vector<std::string> dropped;

  void say(const std::string& message)
  {
    status = message;
    std::cout << message << std::endl;
  }

  bool load(const std::string& path)
  {
    std::string error;
    if (!session.load(path, error)) {
      say("cannot load: " + error);
      return false;
    }
    camera.frame(session);
    picked.reset();
    showing_before = false;
    region_radius = 0.07 * session.box_diagonal();
    std::snprintf(path_field, sizeof path_field, "%s", path.c_str());
    std::snprintf(save_field, sizeof save_field, "%s", session.default_save_path().c_str());
    say("loaded " + path + ": " + std::to_string(num_vertices(session.mesh())) + " vertices, " +
        std::to_string(num_faces(session.mesh())) + " faces, " +
        std::to_string(session.number_of_lines()) + " highlight lines");
    return true;
  }

  bool change_lights(const Light_controls& controls)
  {
    std::string error;
    if (!session.set_light_controls(controls, error)) {
      say("lights: " + error);
      return false;
    }
    if (scripted) // the time of each step of a scripted sweep, on the terminal
      std::printf("lights: %zu segments, updated in %.2f ms\n", session.line_segments().size(),
                  session.update_milliseconds());
    return true;
  }

  // The model cut along the creases sharper than `degrees`, or the paper's (none).
  bool set_creases(std::optional<double> degrees)
  {
    std::string error;
    if (!session.set_crease_angle(degrees, error)) {
      say("creases: " + error);
      return false;
    }
    if (degrees) {
      crease_angle = *degrees;
      std::ostringstream message;
      message << "cut along " << session.number_of_crease_edges()
              << " crease edges (normals differ by more than " << *degrees << " degrees)";
      say(message.str());
    } else
      say("no creases: the paper's model");
    return true;
  }

  bool pick(const Ray& ray)
  {
    picked = first_hit(session.mesh(), ray);
    std::ostringstream message;
    message.precision(17);
    message << "pick: ray " << ray.origin[0] << ' ' << ray.origin[1] << ' ' << ray.origin[2]
            << " direction " << ray.direction[0] << ' ' << ray.direction[1] << ' '
            << ray.direction[2];
    if (picked)
      message << " -> face " << std::size_t(picked->first) << " at " << picked->second;
    else
      message << " -> no face";
    say(message.str());
    if (picked)
      grow();
    return bool(picked);
  }
  void grow()
  {
    if (!picked)
      return;
    session.set_region(grown_region(session.mesh(), picked->first, picked->second, region_radius));
    say("region: " + std::to_string(session.region().size()) + " faces, " +
        std::to_string(session.movable_vertices().size()) + " movable vertices, " +
        std::to_string(session.desired_lines().size()) + " desired lines" +
        (session.region_note().empty() ? "" : " (" + session.region_note() + ")"));
  }
  // A dent at the picked point, of `depth` times the mesh's diagonal, over 0.6 times the
  // region's radius; the region is grown again around it.
  void press_dent(double depth)
  {
    if (!picked)
      return;
    session.press_dent(picked->second, 0.6 * region_radius, depth * session.box_diagonal());
    grow();
  }

  bool fair()
  {
    if (showing_before) {
      session.show_before(false);
      showing_before = false;
    }
    std::string error;
    if (!session.start_fairing(unsigned(std::max(fairing_iterations, 1)), error)) {
      say("fair: " + error);
      return false;
    }
    say("fairing " + std::to_string(session.region().size()) + " faces...");
    return true;
  }

  // ---- Script ---------------------------------------------------------------------------------

  bool read_script(const std::string& path)
  {
    std::ifstream in(path);
    if (!in)
      return false;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      const std::size_t hash = line.find('#');
      if (hash != std::string::npos)
        line.erase(hash);
      if (line.find_first_not_of(" \t\r") != std::string::npos)
        script.emplace_back(number, line);
    }
    scripted = true;
    return true;
  }

  // Runs one action; false if it failed.
  bool run_action(const std::string& line)
  {
    std::istringstream in(line);
    std::string action;
    in >> action;
    auto needs_mesh = [&] {
      if (!session.has_mesh())
        say(action + ": no mesh loaded");
      return session.has_mesh();
    };
    auto numbers = [&](std::initializer_list<double*> values) {
      for (double* v : values)
        if (!(in >> *v)) {
          say(action + ": expected " + std::to_string(values.size()) + " number(s)");
          return false;
        }
      return true;
    };
    if (action == "load") {
      std::string path;
      in >> path;
      return load(path);
    }
    if (action == "quit") {
      glfwSetWindowShouldClose(window, GLFW_TRUE);
      return true;
    }
    if (action == "screenshot") {
      in >> pending_screenshot; // written after this frame is drawn
      return !pending_screenshot.empty();
    }
    if (!needs_mesh())
      return false;
    if (action == "lights") {
      std::string what;
      in >> what;
      Light_controls c = session.light_controls();
      double x = 0, y = 0, z = 0;
      if (what == "direction") {
        if (!numbers({&x, &y, &z}))
          return false;
        std::string error;
        if (!session.set_light_direction(Vector(x, y, z), error)) {
          say("lights: " + error);
          return false;
        }
        return true;
      }
      if (!numbers({&x}))
        return false;
      if (what == "angle")
        c.angle_degrees = x;
      else if (what == "tilt")
        c.tilt_degrees = x;
      else if (what == "offset")
        c.offset = x;
      else if (what == "spacing")
        c.spacing = x;
      else {
        say("lights: unknown setting " + what);
        return false;
      }
      return change_lights(c);
    }
    if (action == "sweep") {
      double steps = 0, delta = 0;
      if (!numbers({&steps, &delta}) || steps < 1)
        return false;
      // One frame per step: queued in front of the rest of the script.
      for (int i = 0; i < int(steps); ++i) {
        std::ostringstream nudge;
        nudge.precision(17);
        nudge << "lights offset " << session.light_controls().offset + delta * (i + 1);
        script.emplace(script.begin() + i, -1, nudge.str());
      }
      return true;
    }
    if (action == "frames") { // draws N frames and reports their mean time
      double count = 0;
      if (!numbers({&count}) || count < 1)
        return false;
      timed_frames = timed_frame_count = int(count);
      timed_start = std::chrono::steady_clock::now();
      return true;
    }
    if (action == "camera") {
      double a = 0, e = 0, zoom = 1;
      if (!numbers({&a, &e, &zoom}) || !(zoom > 0))
        return false;
      camera.azimuth = a;
      camera.elevation = std::clamp(e, -89.0, 89.0);
      camera.zoom = zoom;
      return true;
    }
    if (action == "zebra" || action == "lines") {
      std::string on;
      in >> on;
      (action == "zebra" ? view.zebra : view.show_lines) = on == "on";
      return on == "on" || on == "off";
    }
    if (action == "creases") {
      std::string value;
      in >> value;
      if (value == "off")
        return set_creases(std::nullopt);
      char* end = nullptr;
      const double degrees = std::strtod(value.c_str(), &end);
      if (value.empty() || *end != '\0') {
        say("creases: expected an angle in degrees or off");
        return false;
      }
      return set_creases(degrees);
    }
    if (action == "pick") {
      double x = 0, y = 0;
      if (!numbers({&x, &y}))
        return false;
      return pick(camera.ray_through(x, y));
    }
    if (action == "pick_face") {
      double id = -1;
      if (!numbers({&id}) || id < 0 || id >= double(num_faces(session.mesh()))) {
        say("pick_face: not a face id");
        return false;
      }
      const Face f(static_cast<Mesh::size_type>(id));
      double c[3] = {0, 0, 0};
      for (Vertex v : CGAL::vertices_around_face(session.mesh().halfedge(f), session.mesh()))
        for (int k = 0; k < 3; ++k)
          c[k] += session.mesh().point(v)[k] / 3;
      picked = std::make_pair(f, Point(c[0], c[1], c[2]));
      grow();
      return true;
    }
    if (action == "grow") {
      if (!numbers({&region_radius}) || !picked) {
        say("grow: needs a radius and a picked face");
        return false;
      }
      grow();
      return true;
    }
    if (action == "dent") {
      double depth = 0.006;
      in >> depth;
      if (!picked) {
        say("dent: pick a point first");
        return false;
      }
      press_dent(depth);
      say("pressed a dent");
      return true;
    }
    if (action == "detect") {
      session.start_detection();
      say("detecting irregular regions...");
      return true;
    }
    if (action == "select_detected") {
      double i = -1;
      if (!numbers({&i}) || i < 0 || i >= double(session.detected().size())) {
        say("select_detected: no such region");
        return false;
      }
      session.set_region(session.detected()[std::size_t(i)].faces);
      picked.reset();
      return true;
    }
    if (action == "fair") {
      double iterations = 50;
      in >> iterations;
      fairing_iterations = int(iterations);
      return fair();
    }
    if (action == "before") {
      std::string on;
      in >> on;
      if ((on != "on" && on != "off") || (on == "on" && !session.can_undo())) {
        say("before: on (with something to compare) or off");
        return false;
      }
      showing_before = on == "on";
      session.show_before(showing_before);
      return true;
    }
    if (action == "undo" || action == "redo") {
      const bool can = action == "undo" ? session.can_undo() : session.can_redo();
      action == "undo" ? session.undo() : session.redo();
      if (!can)
        say(action + ": nothing to " + action);
      return can;
    }
    if (action == "save" || action == "save_lines" || action == "save_region" ||
        action == "save_lights") {
      std::string path;
      in >> path;
      const bool ok = action == "save"          ? session.save_mesh(path)
                      : action == "save_lines"  ? session.save_lines(path)
                      : action == "save_region" ? session.save_region(path)
                                                : session.save_lights(path);
      say(ok ? "wrote " + path : action + ": cannot write " + path);
      return ok;
    }
    say("unknown action: " + action);
    return false;
  }

  // One action per frame; none while a computation runs (the script waits for it).
  void step_script()
  {
    if (timed_frames > 0 && --timed_frames == 0) {
      std::printf("frames: %.2f ms per frame\n", std::chrono::duration<double, std::milli>(
                                                     std::chrono::steady_clock::now() - timed_start)
                                                         .count() /
                                                     timed_frame_count);
    }
    // ImGui sizes its windows in the first frames: the script starts once the panel is drawn.
    if (!scripted || script_failed || session.job_running() || !pending_screenshot.empty() ||
        frames < 3 || timed_frames > 0)
      return;
    if (script.empty()) { // the user takes over
      scripted = false;
      say("script done");
      return;
    }
    const auto [number, line] = script.front();
    script.pop_front();
    if (!run_action(line)) {
      std::cerr << "highlight_lines_viewer: script line " << number << " failed: " << line << "\n";
      script_failed = true;
      glfwSetWindowShouldClose(window, GLFW_TRUE);
    }
  }

  // ---- Mouse and keys -------------------------------------------------------------------------

  // Button presses come as events: a click can start and end between two frames, where the
  // buttons' state would miss it.
  void on_mouse_button(int button, int action, int mods)
  {
    if (action == GLFW_RELEASE) {
      dragged_button = -1;
      return;
    }
    if (ImGui::GetIO().WantCaptureMouse || !session.has_mesh())
      return;
    if (button == GLFW_MOUSE_BUTTON_LEFT && (mods & GLFW_MOD_SHIFT))
      pick_requested = true;
    else
      dragged_button = button;
  }

  void handle_mouse()
  {
    ImGuiIO& io = ImGui::GetIO();
    double x = 0, y = 0;
    glfwGetCursorPos(window, &x, &y);
    int window_width = 1, window_height = 1;
    glfwGetWindowSize(window, &window_width, &window_height);
    // Framebuffer pixels (differ from window units on high-density screens).
    const double scale = double(camera.width) / double(std::max(window_width, 1));
    x *= scale;
    y *= scale;
    const double dx = x - last_x, dy = y - last_y;
    last_x = x;
    last_y = y;
    if (pick_requested && !session.job_running())
      pick(camera.ray_through(x, y));
    pick_requested = false;
    const bool dragging = dragged_button >= 0;
    const bool left = dragged_button == GLFW_MOUSE_BUTTON_LEFT;
    if (scroll != 0 && !io.WantCaptureMouse)
      camera.zoom = std::clamp(camera.zoom * std::pow(1.15, scroll), 0.05, 100.0);
    scroll = 0;
    if (!dragging || !session.has_mesh() || (dx == 0 && dy == 0))
      return;
    const bool control = glfwGetKey(window, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS ||
                         glfwGetKey(window, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
    if (control) { // the lights
      Light_controls c = session.light_controls();
      if (left) {
        c.offset += dx / 60;
        c.tilt_degrees = std::clamp(c.tilt_degrees + dy * 0.2, -85.0, 85.0);
      } else {
        c.angle_degrees += dx * 0.3;
      }
      change_lights(c);
    } else if (left) {
      camera.azimuth -= dx * 0.3;
      camera.elevation = std::clamp(camera.elevation + dy * 0.3, -89.0, 89.0);
    } else {
      camera.pan(dx, dy);
    }
  }

  void on_key(int key, int action, int mods)
  {
    if (action == GLFW_RELEASE || ImGui::GetIO().WantCaptureKeyboard || !session.has_mesh())
      return;
    Light_controls c = session.light_controls();
    const bool control = mods & GLFW_MOD_CONTROL;
    switch (key) {
    case GLFW_KEY_LEFT:
      c.offset -= 0.05;
      break;
    case GLFW_KEY_RIGHT:
      c.offset += 0.05;
      break;
    case GLFW_KEY_UP:
      c.spacing *= 1.05;
      break;
    case GLFW_KEY_DOWN:
      c.spacing /= 1.05;
      break;
    case GLFW_KEY_A:
      c.angle_degrees -= 2;
      break;
    case GLFW_KEY_D:
      c.angle_degrees += 2;
      break;
    case GLFW_KEY_W:
      c.tilt_degrees = std::min(c.tilt_degrees + 2, 85.0);
      break;
    case GLFW_KEY_S:
      c.tilt_degrees = std::max(c.tilt_degrees - 2, -85.0);
      break;
    case GLFW_KEY_Z:
      if (control)
        session.undo();
      else
        view.zebra = !view.zebra;
      return;
    case GLFW_KEY_Y:
      if (control)
        session.redo();
      return;
    case GLFW_KEY_L:
      view.show_lines = !view.show_lines;
      return;
    case GLFW_KEY_C:
      if (action == GLFW_PRESS)
        set_creases(session.crease_angle() ? std::nullopt : std::optional<double>(crease_angle));
      return;
    case GLFW_KEY_F:
      if (action == GLFW_PRESS)
        fair();
      return;
    case GLFW_KEY_ESCAPE:
      session.cancel();
      return;
    default:
      return;
    }
    change_lights(c);
  }

  // ---- Panel ----------------------------------------------------------------------------------

  void panel()
  {
    // A side panel as high as the window; the view is centred in the rest.
    ImGui::SetNextWindowPos(ImVec2(6, 6), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(float(panel_width - 6), float(camera.height - 12)),
                             ImGuiCond_Always);
    ImGui::Begin("Highlight lines", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    ImGui::InputText("##path", path_field, sizeof path_field);
    ImGui::SameLine();
    if (ImGui::Button("Open"))
      load(path_field);
    if (!session.has_mesh()) {
      ImGui::TextWrapped("%s", status.c_str());
      ImGui::End();
      return;
    }
    ImGui::Text("%zu vertices, %zu faces", std::size_t(num_vertices(session.mesh())),
                std::size_t(num_faces(session.mesh())));

    if (ImGui::CollapsingHeader("Lights", ImGuiTreeNodeFlags_DefaultOpen)) {
      Light_controls c = session.light_controls();
      float angle = float(c.angle_degrees), tilt = float(c.tilt_degrees), offset = float(c.offset),
            spacing = float(c.spacing);
      bool changed = ImGui::SliderFloat("turn", &angle, -180, 180, "%.1f deg");
      changed |= ImGui::SliderFloat("tilt", &tilt, -85, 85, "%.1f deg");
      changed |= ImGui::DragFloat("across", &offset, 0.01f, -1000, 1000, "%.2f spacings");
      changed |= ImGui::DragFloat("spacing", &spacing, float(c.spacing) * 0.005f,
                                  float(1e-6 * session.box_diagonal()),
                                  float(session.box_diagonal()), "%.4g");
      if (changed) {
        c.angle_degrees = angle;
        c.tilt_degrees = tilt;
        c.offset = offset;
        c.spacing = spacing;
        change_lights(c);
      }
      if (ImGui::Button("Reset lights")) {
        Light_controls reset;
        reset.spacing = CGAL::to_double(session.reference_lights().spacing());
        change_lights(reset);
      }
      ImGui::Text("%zu segments (lights %lld to %lld)", session.line_segments().size(),
                  session.levels().first, session.levels().second);
      ImGui::Text("updated in %.2f ms; frame %.1f ms", session.update_milliseconds(),
                  1000.0 / std::max(ImGui::GetIO().Framerate, 1e-3f));
      ImGui::Checkbox("zebra stripes", &view.zebra);
      ImGui::SameLine();
      ImGui::Checkbox("lines", &view.show_lines);
      bool cut = bool(session.crease_angle());
      if (ImGui::Checkbox("cut along creases", &cut))
        set_creases(cut ? std::optional<double>(crease_angle) : std::nullopt);
      if (cut) {
        // Applied when the slider is released: each angle finds the creases and cuts anew.
        if (!crease_slider_held)
          crease_slider = float(crease_angle);
        ImGui::SliderFloat("crease angle", &crease_slider, 1, 179, "%.0f deg");
        crease_slider_held = ImGui::IsItemActive();
        if (ImGui::IsItemDeactivatedAfterEdit())
          set_creases(double(crease_slider));
        ImGui::Text("%zu crease edges", session.number_of_crease_edges());
      }
    }

    if (ImGui::CollapsingHeader("Region", ImGuiTreeNodeFlags_DefaultOpen)) {
      ImGui::TextDisabled("shift + click on the mesh to pick");
      float radius = float(region_radius);
      if (ImGui::SliderFloat("radius", &radius, float(0.002 * session.box_diagonal()),
                             float(0.3 * session.box_diagonal()), "%.4g")) {
        region_radius = radius;
        grow();
      }
      ImGui::TextWrapped("%zu faces, %zu movable vertices (green), %zu desired lines (blue)",
                         session.region().size(), session.movable_vertices().size(),
                         session.desired_lines().size());
      if (!session.region_note().empty())
        ImGui::TextWrapped("%s", session.region_note().c_str());
      if (ImGui::Button("Clear region")) {
        session.clear_region();
        picked.reset();
      }
      ImGui::SameLine();
      ImGui::BeginDisabled(!picked || session.job_running());
      if (ImGui::Button("Press a dent here"))
        press_dent(0.006);
      ImGui::EndDisabled();
    }

    if (ImGui::CollapsingHeader("Detection", ImGuiTreeNodeFlags_DefaultOpen)) {
      if (session.detection_running()) {
        ImGui::ProgressBar(float(session.detection_fraction()));
        if (ImGui::Button("Cancel"))
          session.cancel();
      } else if (ImGui::Button("Detect irregular regions")) {
        session.start_detection();
      }
      ImGui::Checkbox("show (red: dent, bump; tan: likely design)", &view.show_detected);
      const auto& found = session.detected();
      for (std::size_t i = 0; i < found.size(); ++i) {
        char label[160];
        std::snprintf(label, sizeof label, "%zu: %s, confidence %.2f, %zu faces", i,
                      HL::to_string(found[i].kind), found[i].confidence, found[i].faces.size());
        if (ImGui::Selectable(label, false)) {
          session.set_region(found[i].faces);
          picked.reset();
        }
      }
    }

    if (ImGui::CollapsingHeader("Fairing", ImGuiTreeNodeFlags_DefaultOpen)) {
      ImGui::SliderInt("iterations", &fairing_iterations, 1, 100);
      if (session.fairing_running()) {
        if (ImGui::Button("Cancel (Esc)"))
          session.cancel();
      } else if (ImGui::Button("Fair region (F)")) {
        fair();
      }
      const auto& iterations = session.fairing_iterations();
      if (!iterations.empty()) {
        const auto& last = iterations.back();
        ImGui::TextWrapped("iteration %zu: F %.4g (q_fair %.4g, q_diff %.4g)", iterations.size(),
                           last.target_value, last.fairness_energy, last.difference_energy);
        ImGui::TextWrapped("step %.3g edge lengths, scale %.2f, %zu vertices held back",
                           last.relative_max_displacement, last.step_scale,
                           last.restrained_vertices);
        std::vector<float> values;
        for (const auto& it : iterations)
          values.push_back(float(it.target_value));
        ImGui::PlotLines("F", values.data(), int(values.size()), 0, nullptr, FLT_MAX, FLT_MAX,
                         ImVec2(0, 50));
      }
      ImGui::BeginDisabled(!session.can_undo());
      if (ImGui::Button("Undo"))
        session.undo();
      ImGui::EndDisabled();
      ImGui::SameLine();
      ImGui::BeginDisabled(!session.can_redo());
      if (ImGui::Button("Redo"))
        session.redo();
      ImGui::EndDisabled();
      ImGui::SameLine();
      ImGui::BeginDisabled(!session.can_undo() && !showing_before);
      if (ImGui::Checkbox("before", &showing_before))
        session.show_before(showing_before);
      ImGui::EndDisabled();
    }

    if (ImGui::CollapsingHeader("Save")) {
      ImGui::InputText("##save", save_field, sizeof save_field);
      const std::string base = save_field;
      const std::string stem = base.substr(0, base.size() - mesh_io::extension(base).size());
      if (ImGui::Button("Mesh"))
        say(session.save_mesh(base) ? "wrote " + base : "cannot write " + base);
      ImGui::SameLine();
      if (ImGui::Button("Lines"))
        say(session.save_lines(stem + ".polylines.txt") ? "wrote " + stem + ".polylines.txt"
                                                        : "cannot write lines");
      ImGui::SameLine();
      if (ImGui::Button("Region"))
        say(session.save_region(stem + ".region.txt") ? "wrote " + stem + ".region.txt"
                                                      : "cannot write region");
      ImGui::SameLine();
      if (ImGui::Button("Screenshot"))
        pending_screenshot = stem + ".png";
    }
    ImGui::Separator();
    ImGui::TextWrapped("%s", status.c_str());
    ImGui::End();
  }

  // The fairing's iterations as they come, on the terminal too.
  void report_progress()
  {
    const auto& iterations = session.fairing_iterations();
    for (; reported_iterations < iterations.size(); ++reported_iterations) {
      const auto& it = iterations[reported_iterations];
      std::printf("  iteration %zu: F %.17g (q_fair %.6g, q_diff %.6g), step %.4g edge lengths\n",
                  reported_iterations + 1, it.target_value, it.fairness_energy,
                  it.difference_energy, it.relative_max_displacement);
    }
    if (iterations.empty())
      reported_iterations = 0;
  }

  void frame()
  {
    const std::string message = session.poll();
    report_progress();
    if (!message.empty())
      say(message);
    for (const std::string& path : dropped)
      load(path);
    dropped.clear();
    step_script();
    ++frames;
    glfwGetFramebufferSize(window, &camera.width, &camera.height);
    camera.shift = std::min(panel_width, camera.width / 2) / 2.0;
    if (!scripted)
      handle_mouse();

    ImGui_ImplOpenGL2_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    panel();
    ImGui::Render();

    session.show_distance_field(view.zebra); // computed only while the zebra is shown
    if (session.has_mesh())
      arrays.update(session);
    draw_scene(session, arrays, camera, view, stripe_texture);
    ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
    if (!pending_screenshot.empty()) {
      const bool ok = write_screenshot(pending_screenshot, camera.width, camera.height);
      say(ok ? "wrote " + pending_screenshot : "cannot write " + pending_screenshot);
      if (!ok && scripted) {
        script_failed = true;
        glfwSetWindowShouldClose(window, GLFW_TRUE);
      }
      pending_screenshot.clear();
    }
    glfwSwapBuffers(window);
  }
};

App* the_app = nullptr; // for GLFW's C callbacks

} // namespace

int main(int argc, char** argv)
{
  std::string mesh_path = std::string(HIGHLIGHT_LINES_DATA_DIR) + "/beetle.off";
  std::string script_path;
  std::optional<double> crease_angle;
  int width = 1280, height = 800;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::cout << usage;
      return 0;
    } else if (a == "--script" && i + 1 < argc) {
      script_path = argv[++i];
    } else if (a == "--crease-angle" && i + 1 < argc) {
      char* end = nullptr;
      crease_angle = std::strtod(argv[++i], &end);
      if (*end != '\0' || !(*crease_angle > 0 && *crease_angle < 180)) {
        std::cerr << "highlight_lines_viewer: --crease-angle must lie strictly between 0 and 180 "
                     "degrees\n";
        return 2;
      }
    } else if (a == "--size" && i + 2 < argc) {
      width = std::atoi(argv[++i]);
      height = std::atoi(argv[++i]);
    } else if (!a.empty() && a[0] == '-') {
      std::cerr << "highlight_lines_viewer: unknown option " << a << "\n" << usage;
      return 2;
    } else {
      mesh_path = a;
    }
  }
  if (width < 64 || height < 64 || width > 8192 || height > 8192) {
    std::cerr << "highlight_lines_viewer: --size must be between 64 and 8192 pixels\n";
    return 2;
  }

  if (!glfwInit()) {
    std::cerr << "highlight_lines_viewer: cannot initialise GLFW (no display?)\n";
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
  glfwWindowHint(GLFW_SAMPLES, 4);
  GLFWwindow* window = glfwCreateWindow(width, height, "Highlight lines", nullptr, nullptr);
  if (!window) {
    std::cerr << "highlight_lines_viewer: cannot open an OpenGL 2.1 window\n";
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);

  int status = 0;
  {
    App app;
    the_app = &app;
    app.window = window;
    // Set before ImGui's, which then forward to them.
    glfwSetScrollCallback(window, [](GLFWwindow*, double, double y) { the_app->scroll += y; });
    glfwSetMouseButtonCallback(window, [](GLFWwindow*, int button, int action, int mods) {
      if (!the_app->scripted)
        the_app->on_mouse_button(button, action, mods);
    });
    glfwSetKeyCallback(window, [](GLFWwindow*, int key, int, int action, int mods) {
      if (!the_app->scripted)
        the_app->on_key(key, action, mods);
    });
    glfwSetDropCallback(window, [](GLFWwindow*, int count, const char** paths) {
      if (count > 0)
        the_app->dropped.push_back(paths[0]);
    });
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr; // no imgui.ini left in the working directory
    ImGui::StyleColorsLight();
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL2_Init();
    app.stripe_texture = make_stripe_texture();
    if (crease_angle) { // for every mesh loaded
      std::string error;
      app.session.set_crease_angle(crease_angle, error);
      app.crease_angle = *crease_angle;
    }

    if (!script_path.empty() && !app.read_script(script_path)) {
      std::cerr << "highlight_lines_viewer: cannot read the script " << script_path << "\n";
      status = 2;
    } else if (!app.scripted || app.script.empty() ||
               app.script.front().second.rfind("load", 0) != 0) {
      if (!app.load(mesh_path))
        status = 1;
    }
    while (status == 0 && !glfwWindowShouldClose(window)) {
      if (app.scripted)
        glfwPollEvents();
      else
        glfwWaitEventsTimeout(app.session.job_running() ? 0.03 : 0.1);
      app.frame();
    }
    if (app.script_failed)
      status = 1;
    app.session.cancel();
    ImGui_ImplOpenGL2_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    the_app = nullptr;
  }
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}
