#pragma once
// The plain description of a scene as the file states it, validated and with meshes loaded, but
// not yet a physical model. Every value a later stage might complain about keeps its FileLoc, so
// that an error found there (an unstable step, a zero-length bar) still names file:line:column.
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/look.hpp"
#include "scene/raw_mesh.hpp"

namespace dinam {

inline constexpr double kNoYield = std::numeric_limits<double>::infinity();

// A sheet's material as textile measurements give it, per unit area and width (material_reader
// turns a `material` with `areal_density` into one; model/face_springs.cpp into springs).
struct SheetDesc {
  double areal_density = 0.0;       // kg/m²
  double stretch_stiffness = 0.0;   // N/m: tension per width over strain, along the grain
  double shear_stiffness = 0.0;     // N/m: in-plane shear force per width over the shear angle
  double bending_rigidity = 0.0;    // N·m: bending moment per width over curvature (KES-F's B)
  double thickness = 0.0;           // m: contact and drawing only
  double yield_stretch = kNoYield;  // N/m: tension per width at which it flows
  double yield_bending = kNoYield;  // N·m/m: moment per width at which a fold sets
};

// Section, elastic and plastic properties of the bars of one object, SI units.
struct MaterialDesc {
  std::string preset;              // the named material it started from (material_presets.hpp)
  std::optional<SheetDesc> sheet;  // a sheet: the section values below are then unused
  double density = 0.0;            // kg/m³
  double youngs_modulus = 0.0;     // E, Pa
  double shear_modulus = 0.0;      // G, Pa
  double area = 0.0;               // A, m²
  double area_moment = 0.0;        // I, m⁴ (bending springs)
  double polar_moment = 0.0;       // J, m⁴ (torsion springs)
  double wire_radius = 0.0;        // m, when the section was given as a circular wire; else 0
  // Perfect elastoplasticity, decoupled per spring kind; kNoYield keeps a kind elastic.
  double yield_axial_force = kNoYield;     // N
  double yield_bending_moment = kNoYield;  // N·m
  double yield_torsion_moment = kNoYield;  // N·m
  // Tearing: a bar breaks for good once its strain or its axial force reaches one of these.
  double breaking_strain = kNoYield;  // (L − L0) / L0
  double breaking_force = kNoYield;   // N, tension (N/m, per width, for a sheet)
  bool can_break() const { return breaking_strain < kNoYield || breaking_force < kNoYield; }
  FileLoc loc;
};

// Which pairs of bars meeting at a node get a bending spring.
enum class BendingPairs {
  kAuto,           // kAll where only wires meet, kMostCollinear where a surface's edges meet
  kMostCollinear,  // each bar with its most nearly collinear partner (a grid bends like beams)
  kAll,            // every pair
  kNone,
};

// Axial viscous dampers on the bars of one object: a coefficient, or a fraction of the critical
// damping of each bar's axial mode, c = 2ζ√(k μ) with μ the reduced mass of its two end nodes.
struct AxialDampingDesc {
  double coefficient = 0.0;  // N·s/m
  double ratio = 0.0;        // ζ, dimensionless
};

struct BoxDesc {
  Vec3 min = Vec3::Zero();  // m, world space
  Vec3 max = Vec3::Zero();
};

// A set of an object's vertices: the union of all three choices.
struct NodeSelection {
  bool all = false;
  std::vector<Index> vertex_ids;  // ids into the object's own mesh vertices
  std::vector<BoxDesc> boxes;     // vertices inside any box (inclusive)
  FileLoc loc;

  bool empty() const { return !all && vertex_ids.empty() && boxes.empty(); }
};

using PinDesc = NodeSelection;

// An initial velocity for some of an object's nodes; later groups override earlier ones.
struct VelocityGroupDesc {
  NodeSelection nodes;
  Vec3 velocity = Vec3::Zero();  // m/s
};

// A multiplier of time for a force or a motion: constant 1, a step at t0, a ramp from 0 at t0 to 1
// at t1, or a sine.
struct TimeProfile {
  enum class Kind { kConstant, kStep, kRamp, kSine };
  Kind kind = Kind::kConstant;
  double start = 0.0;      // s, t0 (step, ramp; sine starts then too)
  double end = 0.0;        // s, t1 (ramp)
  double frequency = 0.0;  // Hz (sine)
  double phase = 0.0;      // rad (sine)

  double operator()(double t) const;
};

// A prescribed motion of an object's pinned nodes: x(t) = x_0 + displacement × profile(t), a
// support that is shaken rather than held still; or each pinned node on its mesh vertex's track in
// a point cache (an animated collider, a hand that carries a cloth), linear between samples.
struct PinMotionDesc {
  Vec3 displacement = Vec3::Zero();  // m, the amplitude
  TimeProfile profile;
  // The point cache's samples, each every vertex of the mesh (RawMesh::vertices, each from its
  // point in the file's own order) placed as the mesh is (samples × vertices), `frames_per_sample`
  // frames apart from t = 0; after the last, the last holds.
  std::vector<Vec3> track;
  double frames_per_sample = 0.0;  // at the scene's fps
  FileLoc loc;

  bool moving() const { return !displacement.isZero() || !track.empty(); }
};

// A part of an object made of another material: every bar whose two ends are both in `nodes`,
// and every edge of the listed mesh faces and lines (those of one of the mesh file's materials or
// groups). Later parts win over earlier ones; other bars keep the object's material.
struct MaterialPartDesc {
  NodeSelection nodes;
  std::vector<Index> mesh_faces;  // ids into the object's mesh.faces
  std::vector<Index> mesh_lines;  // ids into the object's mesh.lines
  MaterialDesc material;
  FileLoc loc;
};

// An object's part in contact (docs/scene-format.md, `contact`): each unset field takes the
// scene's `contact` value.
struct ObjectContactDesc {
  std::optional<bool> objects;   // touches other objects
  std::optional<bool> self;      // touches itself
  std::optional<double> radius;  // m, of its bars as capsules and its faces as shells; default:
                                 // each bar's wire radius
  FileLoc radius_loc;            // where `radius` was given (unknown when it was not)
  std::optional<bool> faces;     // its faces are shells; default: unless drawn as wires (a net
                                 // of cords has holes between them)
};

// Nodes of one object tied to another (`attach`): each to its nearest point, at the start, on the
// target's bars and faces, which then moves with the target; held at its start offset from it
// (or, with `swings`, at its start distance, free to swing around it) by a spring of `stiffness`,
// or rigidly (empty: as stiff as the step allows, or a constraint under `integrator: xpbd`);
// broken for good once it pulls harder than `break_force`.
struct AttachmentDesc {
  NodeSelection nodes;  // of the object that holds the attachment
  std::string target;   // another object's name
  FileLoc target_loc;
  std::optional<double> stiffness;  // N/m; empty: rigid
  double break_force = kNoYield;    // N
  bool swings = false;              // holds the distance alone (a loop on a pole, a ring on a hook)
  FileLoc loc;
};

// What an object's faces are to its motion (`faces`): cloth, whose faces resist in-plane shear
// (and carry a sheet material's mass and stiffness); or a net, whose faces are the openings
// between wires, so that only the bars act.
enum class FaceRole { kSheet, kNet };

// How an object is drawn: its faces as a surface, its bars as wires, or both.
enum class DrawStyle { kSurface, kWire, kBoth };

// The default `mesh: {weld}`: bars shorter than a tenth of the object's median bar are collapsed.
// Such a bar, a sliver left by a modelling tool, would alone set a time step hundreds of times
// shorter than the rest of the mesh needs: the bending and torsion springs at its ends vibrate as
// (L_median / L)³ faster, over node masses that the long bars set. Collapsing it moves a corner by
// at most a tenth of a typical bar, below what the motion shows.
inline constexpr double kDefaultWeldFraction = 0.1;

// A collider's shell when neither its contact nor a material gives one (`role: collider`): thick
// enough that a cloth falling at 2 m/s does not pass it in a millisecond's step.
inline constexpr double kColliderShell = 0.005;  // m

struct ObjectDesc {
  std::string name;
  FileLoc loc;
  // `role: collider`: an obstacle held whole (every node pinned, or moved by `pin_motion`), which
  // needs no material and is warned of nothing a material would decide.
  bool collider = false;
  RawMesh mesh;         // in world space
  Placement placement;  // how the mesh file's vertices were placed there
  FileLoc mesh_loc;
  std::string mesh_source = "the mesh";  // for messages: "mesh file '…'" or "the generated mesh"
  // Bars shorter than this fraction of the object's median bar length are collapsed before the
  // model is built (`mesh: {weld}`); 0 keeps every bar.
  double weld_fraction = kDefaultWeldFraction;
  FileLoc weld_loc;
  MaterialDesc material;
  std::vector<MaterialPartDesc> parts;  // bars of other materials
  ObjectContactDesc contact;
  PinDesc pins;
  bool pins_clamped = false;  // the pinned nodes hold the direction of their bars as well
  PinMotionDesc pin_motion;   // none by default: pinned nodes stay where they are
  std::vector<AttachmentDesc> attachments;  // its nodes tied to other objects
  Vec3 initial_velocity = Vec3::Zero();     // m/s
  std::vector<VelocityGroupDesc> velocity_groups;
  BendingPairs bending_pairs = BendingPairs::kAuto;
  FaceRole faces = FaceRole::kSheet;
  FileLoc faces_loc;    // of `faces`, when given
  bool torsion = true;  // torsion springs wherever a bar has reference neighbours
  AxialDampingDesc axial_damping;
  Vec3f color{0.8f, 0.8f, 0.8f};        // linear RGB in [0, 1]
  std::optional<double> render_radius;  // m; default: the wire radius, at least a visible minimum
  DrawStyle style = DrawStyle::kWire;   // default: surface when the mesh has faces
  bool joints = true;                   // spheres at the nodes of wires, so bars meet smoothly
  std::optional<int> subdivide;         // levels its surface is smoothed by; default: by its size
  Shading shading = Shading::kSmooth;
  double sharp_angle = kDefaultSharpAngle;  // degrees, for Shading::kAuto
  std::filesystem::path texture;            // a PNG laid on the surface by the mesh uv; optional
  FileLoc texture_loc;                      // the 'texture' key, or the mesh's for its own texture
  Finish finish;                            // how its surface takes the light (core/look.hpp)
};

// A camera key of a path: where the eye is at a time, what it looks at, its field of view.
struct CameraKeyDesc {
  double time = 0.0;  // s
  Vec3 position = Vec3::Zero();
  Vec3 look_at = Vec3::Zero();
  double fov_degrees = 40.0;
  FileLoc loc;
};

// A camera circling a centre at a height, looking at it.
struct OrbitDesc {
  std::optional<Vec3> center;    // m; default: the centre of the motion's subject
  std::optional<double> radius;  // m, horizontal; default: far enough to see all of the subject
  double height = 0.0;           // m, of the eye above the centre; default: a fifth of the radius
  bool height_given = false;
  double turns = 1.0;            // over the duration; negative turns clockwise seen from above
  double start_degrees = -90.0;  // where the eye starts, around the up axis from +x
};

struct CameraDesc {
  // kFixed: position and look_at as given. kAuto: looks along `direction` at the motion's
  // bounding box over every frame, just far enough to see all of it. kFollow: keeps `offset`
  // from the centroid of `follow`'s nodes. kPath: moves smoothly through `keys`. kOrbit: circles
  // as `orbit` says.
  enum class Mode { kFixed, kAuto, kFollow, kPath, kOrbit };
  Mode mode = Mode::kAuto;
  Vec3 position{4.0, -6.0, 3.0};  // m
  Vec3 look_at{0.0, 0.0, 1.0};    // m
  Vec3 up = kWorldUp;
  double fov_degrees = 40.0;           // vertical
  Vec3 direction{-0.55, 0.75, -0.36};  // auto: from the eye towards the scene
  std::string follow;                  // follow: the object's name
  Vec3 offset{3.0, -4.0, 1.5};         // follow: eye minus target, m
  std::vector<CameraKeyDesc> keys;     // path: at increasing times
  OrbitDesc orbit;
  FileLoc loc;
};

// Motion blur: each frame is the mean of `samples` instants spread evenly over a shutter interval
// of `shutter` frame intervals centred on the frame's time, each at a step of the simulation.
struct MotionBlurDesc {
  int samples = 1;       // 1: none
  double shutter = 0.5;  // fraction of the frame interval, in (0, 1]

  bool enabled() const { return samples > 1; }
};

// Presets of the picture's features: `draft` for quick looks, `standard` (the default), `final`
// for frames to show. Keys given beside `quality` override the preset's choice.
enum class QualityPreset { kDraft, kStandard, kFinal };

// Picture quality, which trades against the time per frame.
struct RenderQualityDesc {
  QualityPreset preset = QualityPreset::kStandard;
  int samples = 4;  // multisampled anti-aliasing; 1 turns it off
  bool shadows = true;
  int shadow_resolution = 2048;  // texels per side
  LookSettings look;             // soft shadows, ambient occlusion, sky light, tone mapping
  MotionBlurDesc motion_blur;
};

// What each preset chooses (docs/scene-format.md has the table).
RenderQualityDesc quality_preset(QualityPreset preset);

enum class MovieFormat { kMp4, kGif, kNone };

// A field force on some nodes: per unit mass (an acceleration, like gravity) or per node.
struct FieldForceDesc {
  Vec3 value = Vec3::Zero();  // m/s² when per_unit_mass, else N on each node
  bool per_unit_mass = true;
  std::string object;   // empty: every object
  NodeSelection nodes;  // within `object`; empty: all its nodes
  TimeProfile profile;
  FileLoc loc;
};

// Wind: a velocity field that drags on mesh faces and on bare bars.
struct WindDesc {
  bool enabled = false;
  Vec3 velocity = Vec3::Zero();   // m/s, the mean
  double gust_amplitude = 0.0;    // m/s, along the mean direction
  double gust_period = 4.0;       // s
  double turbulence = 0.0;        // m/s, amplitude of smooth seeded noise in each direction
  double turbulence_scale = 2.0;  // m, length scale of the noise (its time scale follows the mean)
  std::uint32_t seed = 1;
  double air_density = 1.225;        // kg/m³
  double face_drag = 1.0;            // drag coefficient of a face, normal flow
  double bar_drag = 1.2;             // drag coefficient of a cylinder in cross flow
  std::vector<std::string> objects;  // empty: every object
};

struct GroundDesc {
  Vec3 point = Vec3::Zero();  // m, a point of the plane
  Vec3 normal = kWorldUp;     // unit, pointing out of the ground
  bool visible = true;
  bool checker = true;  // a checkerboard, or plain
  // Linear RGB: the ground's colour (a plain ground's, the checker's lighter squares), the
  // checker's other squares, and the squares' size (empty: from the scene's extent).
  Vec3f color{0.60f, 0.58f, 0.54f};
  Vec3f checker_color{0.50f, 0.48f, 0.45f};
  std::optional<double> tile;  // m
  // A seamless studio backdrop (drawing only): the floor curves up into a wall around the scene,
  // far enough that every camera stands inside it (visual/backdrop.hpp).
  bool cyclorama = false;
  bool contact = true;
  // Penalty stiffness per node: empty for auto (a contact frequency an eighth of the model's
  // highest).
  std::optional<double> stiffness;  // N/m
  FileLoc stiffness_loc;            // where `stiffness` was given as a number
  double damping_ratio = 0.3;       // of the contact oscillation; normal direction only
  double static_friction = 0.5;     // μs
  double kinetic_friction = 0.4;    // μk
  bool stick = false;               // no sliding at all (the paper's falling ball)
  FileLoc loc;
};

// The sky's colours, linear RGB: at the horizon and at the top of the picture; they light the
// scene too (`sky_light`).
struct SkyDesc {
  Vec3f horizon{0.78f, 0.82f, 0.86f};
  Vec3f zenith{0.30f, 0.45f, 0.68f};
};

// Contact between objects and within one (dynamics/contact/object_contact.hpp): bars are capsules
// and faces thin shells that push apart by a penalty, with Coulomb friction. Off unless asked for.
struct ContactDesc {
  bool objects = false;             // between different objects
  bool self = false;                // within one object
  std::optional<double> stiffness;  // N/m per contact; empty for auto (a contact frequency half
                                    // the model's highest, like the ground's)
  double damping_ratio = 0.3;       // of the contact oscillation; normal direction only
  double static_friction = 0.5;     // μs
  double kinetic_friction = 0.4;    // μk
  FileLoc loc;
  FileLoc stiffness_loc;  // where `stiffness` was given as a number
};

// How the settling phase finds the structure at rest: the static equilibrium by Newton's method
// on the potential energy, or dynamic relaxation (stepping in time, damped, until it stops).
enum class SettleMethod { kNewton, kRelax };

// How the motion is integrated in time (`integrator`): central differences, explicit, whose step
// the stiffest bar bounds; backward Euler or BDF2, implicit (solver/implicit_integrator.hpp), whose
// step is chosen for accuracy; or central differences with the bars held as constraints
// (dynamics/bar_constraints.hpp: XPBD), whose step the softer springs bound: the solver for
// stiff threads.
enum class IntegratorKind { kCentralDifference, kImplicit, kXpbd };

// The implicit integrator's steps per frame where `timestep` does not say.
inline constexpr int kImplicitStepsPerFrame = 4;

// The implicit integrator's formula (`integrator: implicit` or `implicit_bdf2`): backward Euler,
// first order, which damps a mode of ω by 1/√(1 + ω²h²) a step; or the two-step backward
// differentiation formula, second order, which damps the modes the step resolves far less and
// the ones it does not still strongly (both are L-stable).
enum class ImplicitScheme { kBackwardEuler, kBdf2 };

// A phase before t = 0 in which the structure comes to rest under gravity alone (no fields, no
// wind, no initial velocities); its final shape is the start of the shown motion. The paper's flag
// begins this way.
struct SettleDesc {
  bool enabled = false;  // false: no settling, the motion starts from the meshes as given
  SettleMethod method = SettleMethod::kNewton;
  double duration = 60.0;    // s, the longest the phase may take to reach `residual`
  double residual = 1.0e-6;  // largest out-of-balance force on a free node / that node's weight
  std::optional<double> damping;  // 1/s, of the first, overdamped stage; empty: automatic
  FileLoc loc;
  FileLoc duration_loc;  // of `duration`, or of the settle map when it is left at its default
};

// One setting that decides the motion: a key path as the file spells it and the text of its
// value. motion_settings.hpp says which keys count; two scenes with the same settings give the same
// motion with one dinam build, so a motion cache made from one serves the other.
struct MotionSetting {
  std::string key;    // e.g. "objects[0].material.density"
  std::string value;  // the YAML scalar as written, or "sha256:…" of a mesh's loaded geometry

  bool operator==(const MotionSetting&) const = default;
};

// What `timestep` as a map asks of the automatic step. By default (and with `timestep: auto`) the
// few nodes that would set a much shorter step than the rest get a little mass (mass scaling, at
// most kDefaultMaxAddedMass of the free nodes' mass). A `target` step, or `max_steps` over the
// duration, is reached by mass scaling within `max_added_mass`, collapsing ever longer short bars
// where that is not enough; a target no such means can reach is an error.
inline constexpr double kDefaultMaxAddedMass = 0.02;

struct StepTargetDesc {
  std::optional<double> target;                  // s
  std::optional<double> max_steps;               // over the duration
  double max_added_mass = kDefaultMaxAddedMass;  // a fraction of the free nodes' mass
  bool mass_scaling = true;                      // false: the default adds no mass
  FileLoc loc;

  bool aims() const { return target.has_value() || max_steps.has_value(); }
};

struct SceneDescription {
  std::filesystem::path source;                // the scene file
  std::string source_sha256;                   // of the scene file's bytes, as sha256sum prints it
  std::vector<MotionSetting> motion_settings;  // what decides the motion, in file order
  int version = 1;
  std::string name;  // movie file name; default: the scene file's stem
  // Values allowed but far outside what is plausible (unit slips), "file:line:col: warning: …",
  // told before a run with the model's (app/command_support.cpp).
  std::vector<std::string> warnings;

  double duration = 0.0;  // s
  FileLoc duration_loc;
  double fps = 0.0;                // frames per second
  std::optional<double> timestep;  // s; empty for `auto`
  IntegratorKind integrator = IntegratorKind::kCentralDifference;
  ImplicitScheme implicit_scheme = ImplicitScheme::kBackwardEuler;
  FileLoc integrator_loc;
  StepTargetDesc step_target;  // what an automatic step aims at
  FileLoc timestep_loc;
  Vec3 gravity{0.0, 0.0, -9.81};  // m/s²
  double global_damping = 0.0;    // 1/s, viscous friction −α m v on every node
  SettleDesc settle;
  std::vector<FieldForceDesc> fields;
  WindDesc wind;

  GroundDesc ground;
  SkyDesc sky;
  ContactDesc contact;
  CameraDesc camera;
  int image_width = 1280;
  int image_height = 720;
  RenderQualityDesc quality;
  Vec3 light_direction{0.35, -0.45, 0.82};  // towards the sun
  double light_size_degrees = 2.0;          // the sun's apparent diameter (soft shadows)
  std::filesystem::path output;             // folder for frames and the movie
  MovieFormat movie = MovieFormat::kMp4;

  std::vector<ObjectDesc> objects;

  // Frame k (0-based) shows time k / fps; duration × fps frames in all.
  int frame_count() const;
  // Whether the integrator's step is bounded by the stiffest springs (central differences'), so
  // that mass scaling can lengthen it; the implicit schemes' is not.
  bool step_bounded_by_stiffness() const { return integrator != IntegratorKind::kImplicit; }
};

// Reads and validates a scene file, loading every mesh it names. Throws UserError naming
// file:line:column for anything wrong, including keys that are never read.
SceneDescription read_scene(const std::filesystem::path& path);

// The same from text already in memory; `source` is only used in messages and to resolve paths.
SceneDescription read_scene_text(const std::string& text, const std::filesystem::path& source);

}  // namespace dinam
