// The scene: every parameter of one run, as plain data in SI units and degrees.
// Values come from assets/ (defaults.json and the presets); scene_json.h reads and writes them and
// scene_validate.h checks them. No defaults live here: a Scene is always resolved from the assets.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace polyroll {

// A hollow regular n-gon: the 3D box whose cross-section the 2D body is.
struct ShellParams {
    std::string preset;                 // the preset these values started from ("" if none)
    int sides = 0;                      // n
    double inner_circumradius_m = 0.0;  // inside centre-to-vertex radius
    double wall_thickness_m = 0.0;      // side walls, measured perpendicular to each face
    double depth_m = 0.0;               // inside length along the roll axis (between the lids)
    double lid_thickness_m = 0.0;       // each of the two end faces
    double mass_kg = 0.0;               // walls plus both lids
    // Share of mass_kg in the two lids; empty = walls and lids of one material (split by volume).
    std::optional<double> lid_mass_fraction;
    // Radius of the rounding of each outer vertex (vertex_rounding.h): the arc the shell rolls over
    // when it turns from one face to the next. The Box2D shell and the 3D reference's edge spheres.
    double vertex_radius_m = 0.0;
};

// A bulk grain material, modelled in 2D as circles.
struct MaterialParams {
    std::string preset;
    double diameter_m = 0.0;           // mean grain diameter
    double diameter_spread = 0.0;      // diameters uniform in d (1 +- spread)
    double bulk_density_kg_m3 = 0.0;   // poured bulk density (mass / bulk volume)
    double friction = 0.0;             // grain on grain
    double wall_friction = 0.0;        // grain on the shell's walls
    double restitution = 0.0;          // grain on grain and on walls
    double packing_fraction = 0.0;     // poured 3D packing: bulk density / grain density
    // Grain on the two lids (end faces), which a 2D disc never touches: a force on each grain
    // opposing its sliding relative to the shell, with the lateral pressure of the pile above it
    // (sim/grains/lid_friction.h). 0 leaves the term out.
    double lid_friction = 0.0;
    // What one 2D disc stands for (sim/geometry/disc_size.h). Unset: a column of grains through the box's
    // depth, so a disc is the grain's size. A number k: k of the 3D fill's grains, so the discs are
    // as many as the fill's grains divided by k, sized to fit the cross-section (k = 1: one disc per
    // grain, each with a grain's mass). A material's value: how fine its 2D pile must be to flow as
    // the 3D fill does, weighed against its cost (assets/materials.json says why for each).
    std::optional<double> grains_per_disc;
};

struct FillParams {
    double ratio = 0.0;  // r: fraction of the inside volume occupied by bulk grains, 0..1
    MaterialParams material;
};

struct RampParams {
    std::string preset;
    double length_m = 0.0;
    double friction = 0.0;      // shell on ramp surface
    double restitution = 0.0;   // shell on ramp surface
    double angle_deg = 0.0;     // theta, from horizontal: the chord's angle on a curved track
    // How fast the local slope falls down the track, about the chord (ramp_profile.h); 0 straight.
    double curvature_deg_per_m = 0.0;
};

// vertex: poured and let go on the downhill vertex; face: poured and let go on face (0, 1);
// tipped: poured with the shell on face (0, 1), then shell and pile turned together onto the
// downhill vertex, as a hand that fills the box on the table and then stands it on its edge.
enum class ReleasePose { vertex, face, tipped };

struct ReleaseParams {
    ReleasePose pose = ReleasePose::vertex;
    // Vertex and tipped releases: rotation past the balance point (centre of the polygon straight above the
    // pivot vertex), downhill. A hand never lets go exactly at balance.
    double tilt_deg = 0.0;
    // The grain pile's free surface at release, turned from level by this (positive: higher on the
    // downhill side), the pile poured below it. The experiment does not say how its piles lay; the 3D
    // reference's pour leaves the octagon's and decagon's leaning downhill, which sets their release
    // and first landing apart from a level pile's (docs/studies/pile-bulk.md). 2D grain model only.
    double pile_tilt_deg = 0.0;
};

// The frame the grain engine steps in (moving_frame.h): the ramp's, or one moving down the track with
// the pile, which gives the same motion in exact arithmetic and keeps Box2D's contact lists short.
enum class EngineFrame { ramp, pile };

// Which pairs of grains the grain engine keeps a contact for (near_pairs.h): every pair whose boxes,
// fattened by Box2D's fixed margin, overlap (boxes, Box2D's own), or only those that touch or nearly
// touch (near). The same motion in exact arithmetic: a contact that does not touch does nothing.
enum class GrainContacts { boxes, near };

// Time step, sub-steps and solver iterations: what the user pays for accuracy.
struct FidelityParams {
    std::string preset;
    double step_hz = 0.0;          // tracker steps per simulated second
    int substeps = 0;              // engine Step calls per tracker step
    int velocity_iterations = 0;
    int position_iterations = 0;
    EngineFrame frame = EngineFrame::ramp;  // the grain engine's frame; what runs report is always the ramp's
    GrainContacts contacts = GrainContacts::boxes;  // which grain pairs the engine keeps a contact for
};

// Which physics computes the run: the grain simulation, or one of the experimenters' reduced models
// (docs/physics.md), which treat the polygon and its fill as one rigid body between impacts; or
// `automatic` ("auto"): the model registry picks per scene (model_choice.h).
// `dem3d` is the 3D reference: the box and every grain of the fill in Yade's discrete element method
// (src/sim/dem3d/), run as a subprocess: a check on the 2D cross-section, never picked by auto.
// Each value but automatic has one row in the model registry (sim/registry/model_rows.cpp), which
// names it and says everything else about it; automatic stays last.
enum class Model { grains, segments, rigid, dem3d, automatic };

// What only the 3D reference (--model dem3d) uses: its soft contacts and the track's channel.
struct Dem3dParams {
    double contact_time_s = 0.0;    // duration of a grain's collision (linear spring-dashpot)
    double time_step_share = 0.0;   // the DEM time step as a share of contact_time_s
    // The width of the track's channel the box rolls in: its sides keep the box, free in all six
    // directions, in the track. Unset: no channel, the box held in its plane as the 2D cross-section is.
    std::optional<double> channel_width_m;
};

// What the one-grain-deep 2D pile lacks against the 3D box (grains slipping along the axis and
// turning out of the plane, the box's depth), stood in for by factors on the 2D contacts' values, fitted
// to the 3D reference's runs (assets/closures.json, assets/reference-3d.json). Only the 2D grain model
// reads them: the 3D reference has those freedoms, and the reduced models have no grain contacts.
struct ClosureParams {
    std::string preset;
    double disc_friction_factor = 1.0;  // disc on disc: the material's friction times this
    double wall_friction_factor = 1.0;  // disc on the shell's walls: the material's wall friction times this
    double restitution_factor = 1.0;    // disc on disc and on walls: the material's restitution times this, at most 1
    // The discs' diameters uniform in d (1 +- this) instead of the material's spread: a 3D pile of equal
    // spheres is disordered, while equal discs in a plane lock into a crystal. Unset: the material's.
    std::optional<double> disc_size_spread;
    // The pile's level holds min(1, r x this) of the inside, the fill's mass unchanged (r x inside volume
    // x bulk density): the 3D box's pour packs looser than the 0.60 its grain count assumes, so its pile
    // stands higher than r (1.08-1.20 times the 2D pile's share of the inside in ten 3D pours,
    // docs/studies/pile-bulk.md), where the 2D discs fill exactly r. More discs, each lighter, in the 3D
    // pile's outline.
    double bulk_factor = 1.0;
};

struct RunParams {
    Model model = Model::grains;
    std::uint64_t seed = 0;
    double time_limit_s = 0.0;
    double sample_hz = 0.0;        // trajectory.csv rows per simulated second
    double gravity_m_s2 = 0.0;
    double settle_time_s = 0.0;    // longest time given to the grains to settle before release
    double rest_speed_m_s = 0.0;   // the shell counts as at rest below this speed...
    double rest_time_s = 0.0;      // ... held for this long
    // The run ends at this face impact (1 = the first face landed), whatever the shell does next: an
    // early exit for a caller that needs no more (calibrate's runs for an observation decided once the
    // shell is past its first impact). 0: never. Read by the shell tracker (the grain and 3D models).
    int end_at_impact = 0;
};

struct Scene {
    ShellParams shell;
    FillParams fill;
    RampParams ramp;
    ReleaseParams release;
    FidelityParams fidelity;
    RunParams run;
    Dem3dParams dem3d;
    ClosureParams closure;
};

}  // namespace polyroll
