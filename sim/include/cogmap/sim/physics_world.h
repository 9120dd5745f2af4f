#pragma once
/// The Box2D side of the simulator: walls and obstacles as static fixtures, the P2-AT as one
/// dynamic box. The body is driven kinematically in its own frame (forward speed and turn rate,
/// no sideways slide, as a skid-steer moves) and contacts stop it.

#include <memory>
#include <optional>

#include "cogmap/mapper/seam/pose2.h"
#include "cogmap/sim/skid_steer.h"
#include "cogmap/sim/world_spec.h"

class b2World;
class b2Body;

namespace cogmap::sim {

/// Body and solver settings. Defaults: the P2-AT of docs/p2at.md, Box2D's recommended
/// iteration counts (8 velocity, 3 position).
struct PhysicsOptions {
  double body_length_m = 0.626;  ///< footprint along x (docs/p2at.md)
  double body_width_m = 0.505;   ///< footprint along y
  double body_mass_kg = 40.0;    ///< ~40 kg (docs/p2at.md)
  double friction = 0.4;         ///< body against walls; rubber tyres and bumpers on plaster
  int velocity_iterations = 8;   ///< Box2D solver iterations per step
  int position_iterations = 3;   ///< Box2D position correction iterations per step
  /// Skip Box2D's step while the body touches nothing and stays clear of every other shape over
  /// the step (the pose is then the free arc either way; docs/performance.md, "Lazy bounces and
  /// other per-frame savings"). false steps Box2D always (the test compares the two).
  bool skip_free_steps = true;
};

/// One Box2D world with the robot in it. Not copyable (Box2D owns raw pointers).
class PhysicsWorld {
 public:
  /// Builds the fixtures from `world` and places the body at world.start.
  PhysicsWorld(const WorldSpec& world, const PhysicsOptions& options = {});
  ~PhysicsWorld();
  PhysicsWorld(const PhysicsWorld&) = delete;
  PhysicsWorld& operator=(const PhysicsWorld&) = delete;

  /// Drives the body at `twist` (robot frame) for dt_s seconds and returns the new true pose.
  /// In free space the pose advances exactly along the arc (the integrator odometry uses, in
  /// double precision); while the body touches something Box2D's solved pose is the truth.
  const mapper::Pose2& step(const BodyTwist& twist, double dt_s);

  /// The true pose, world frame.
  const mapper::Pose2& pose() const { return pose_; }

  /// True when the body touched a wall or an obstacle during the last step.
  bool in_contact() const { return in_contact_; }

  /// Steps that skipped Box2D (PhysicsOptions::skip_free_steps) so far.
  long skipped_steps() const { return skipped_steps_; }

  /// Number of static fixtures built from the world (walls, obstacles).
  int static_fixture_count() const { return static_fixtures_; }

 private:
  /// True when the body touches nothing and stays farther than a margin from every other shape
  /// over a step that moves its points by at most step_reach_m, so a Box2D step would move it
  /// freely.
  bool clear_of_obstacles(double step_reach_m);
  /// Least distance from the body's outline to any other shape (rounded outlines, as Box2D's
  /// contacts see them), capped at kQueryReachM.
  double clearance_m() const;

  PhysicsOptions options_;
  std::unique_ptr<b2World> world_;
  b2Body* body_ = nullptr;  ///< owned by world_
  double half_diagonal_m_;  ///< how far a body point can lie from its centre
  mapper::Pose2 pose_;
  long skipped_steps_ = 0;
  /// The body's pose when clearance_m_ was measured (clear_of_obstacles).
  mapper::Pose2 measured_at_;
  double clearance_m_ = 0.0;
  bool clearance_known_ = false;
  bool in_contact_ = false;
  int static_fixtures_ = 0;
};

}  // namespace cogmap::sim
