#include "cogmap/sim/physics_world.h"

#include <box2d/b2_distance.h>
#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "cogmap/sim/world_geometry.h"
#include "world/polygon_ops.h"

namespace cogmap::sim {

namespace {

// Triangles thinner than this (m²) would trip Box2D's hull welding; validation already
// rejects polygons under 1 cm², so only slivers of an ear-clipped polygon can hit it.
constexpr double kMinFixtureAreaM2 = 1e-5;

b2Vec2 to_b2(const mapper::Point2& p) {
  return {static_cast<float>(p.x()), static_cast<float>(p.y())};
}

// True when b2PolygonShape::Set accepts `pts` instead of asserting: at least 3 vertices left
// after it welds those closer than b2_linearSlop / 2, and a hull of non-zero float area. The
// loader's limits (1 cm features, 1 km coordinates) keep valid worlds far from this; mitred
// joints of very short segments can still produce slivers, which are skipped, not fatal.
bool box2d_accepts(const std::vector<b2Vec2>& pts) {
  constexpr float kWeld = 0.5f * b2_linearSlop;
  std::vector<b2Vec2> unique;
  for (const b2Vec2& v : pts) {
    bool fresh = true;
    for (const b2Vec2& u : unique) fresh = fresh && b2DistanceSquared(v, u) >= kWeld * kWeld;
    if (fresh) unique.push_back(v);
  }
  if (unique.size() < 3 || unique.size() > static_cast<std::size_t>(b2_maxPolygonVertices)) {
    return false;
  }
  // Twice the area of the fan from the first vertex, in float like Box2D's centroid.
  float twice_area = 0.0f;
  for (std::size_t i = 1; i + 1 < unique.size(); ++i) {
    twice_area += b2Cross(unique[i] - unique[0], unique[i + 1] - unique[0]);
  }
  return std::abs(0.5f * twice_area) > 100.0f * b2_epsilon;
}

// A skipped step leaves every shape at least this far apart (m): Box2D calls two shapes touching
// once their rounded outlines meet (distance 0), so the margin only has to cover float rounding;
// 3 cm is plenty. The test SkippingFreeStepsChangesNothing still passes at 0 and fails at -2 cm.
constexpr double kSkipMarginM = 0.03;
// The clearance query looks this far beyond the body's half diagonal: farther fixtures bound the
// clearance without a distance computation. 1 m holds a corridor's walls for ~2 s of driving.
constexpr double kQueryReachM = 1.0;
// Near a wall (no skip) the clearance is measured again only after the body moved this far (m):
// Box2D steps meanwhile, which is always right.
constexpr double kRemeasureAfterM = 0.05;

int add_convex(b2Body* body, const mapper::Polyline& outline) {
  if (std::abs(geom::signed_area(outline)) < kMinFixtureAreaM2) return 0;
  std::vector<b2Vec2> pts;
  for (const mapper::Point2& p : outline) pts.push_back(to_b2(p));
  if (!box2d_accepts(pts)) return 0;
  b2PolygonShape shape;
  shape.Set(pts.data(), static_cast<int32>(pts.size()));
  body->CreateFixture(&shape, 0.0f);
  return 1;
}

int add_piece(b2Body* body, const SolidPiece& piece) {
  if (piece.circle) {
    b2CircleShape shape;
    shape.m_p = to_b2(piece.circle_center);
    shape.m_radius = static_cast<float>(piece.circle_radius_m);
    body->CreateFixture(&shape, 0.0f);
    return 1;
  }
  if (piece.convex && static_cast<int>(piece.outline.size()) <= b2_maxPolygonVertices) {
    return add_convex(body, piece.outline);
  }
  int n = 0;
  for (const mapper::Polyline& tri : geom::triangulate(piece.outline)) n += add_convex(body, tri);
  return n;
}

}  // namespace

PhysicsWorld::PhysicsWorld(const WorldSpec& world, const PhysicsOptions& options)
    : options_(options),
      world_(std::make_unique<b2World>(b2Vec2(0.0f, 0.0f))),
      half_diagonal_m_(0.5 * std::hypot(options.body_length_m, options.body_width_m)) {
  b2BodyDef ground_def;  // static by default
  b2Body* ground = world_->CreateBody(&ground_def);
  for (const SolidPiece& piece : solid_pieces(world)) static_fixtures_ += add_piece(ground, piece);

  b2BodyDef body_def;
  body_def.type = b2_dynamicBody;
  body_def.position = to_b2(world.start.translation());
  body_def.angle = static_cast<float>(world.start.theta_rad);
  body_def.allowSleep = false;  // velocity is set every step; a sleeping body would ignore it
  body_ = world_->CreateBody(&body_def);
  b2PolygonShape box;
  box.SetAsBox(static_cast<float>(0.5 * options.body_length_m),
               static_cast<float>(0.5 * options.body_width_m));
  b2FixtureDef fixture;
  fixture.shape = &box;
  fixture.density =
      static_cast<float>(options.body_mass_kg / (options.body_length_m * options.body_width_m));
  fixture.friction = static_cast<float>(options.friction);
  body_->CreateFixture(&fixture);
  pose_ = world.start;
}

PhysicsWorld::~PhysicsWorld() = default;

double PhysicsWorld::clearance_m() const {
  // Fixtures whose (fattened) box overlaps a box of half side reach about the body: every other
  // shape lies outside that box, so at least reach - half diagonal from the body in any heading.
  const double reach_m = half_diagonal_m_ + kQueryReachM;
  struct Nearby final : b2QueryCallback {
    const b2Body* self;
    std::vector<b2Fixture*> fixtures;
    explicit Nearby(const b2Body* body) : self(body) {}
    bool ReportFixture(b2Fixture* fixture) override {
      if (fixture->GetBody() != self) fixtures.push_back(fixture);
      return true;
    }
  } query(body_);
  const b2Vec2 c = body_->GetPosition();
  const auto r = static_cast<float>(reach_m);
  b2AABB box;
  box.lowerBound = c - b2Vec2(r, r);
  box.upperBound = c + b2Vec2(r, r);
  world_->QueryAABB(&query, box);
  // (Less the body's own rounding, which lies outside its box.)
  double clearance = kQueryReachM - b2_polygonRadius;
  const b2Fixture* own = body_->GetFixtureList();
  for (const b2Fixture* fixture : query.fixtures) {
    for (int32 child = 0; child < fixture->GetShape()->GetChildCount(); ++child) {
      b2DistanceInput in;
      in.proxyA.Set(own->GetShape(), 0);
      in.proxyB.Set(fixture->GetShape(), child);
      in.transformA = body_->GetTransform();
      in.transformB = fixture->GetBody()->GetTransform();
      in.useRadii = true;  // the rounded outlines Box2D's contacts test
      b2SimplexCache cache;
      cache.count = 0;
      b2DistanceOutput out;
      b2Distance(&out, &cache, &in);
      clearance = std::min(clearance, static_cast<double>(out.distance));
    }
  }
  return clearance;
}

bool PhysicsWorld::clear_of_obstacles(double step_reach_m) {
  // A touching contact needs Box2D's solver. Otherwise a step whose body stays farther than
  // kSkipMarginM from every other shape can neither touch anything nor create a contact that
  // touches, so the body moves freely and its pose is the free arc: the step is skipped. Box2D
  // catches up on the contacts' bookkeeping (new pairs, pairs that parted) at its next step,
  // always before any shape can touch.
  for (b2ContactEdge* edge = body_->GetContactList(); edge != nullptr; edge = edge->next) {
    if (edge->contact->IsTouching()) return false;
  }
  // How far any point of the body has moved since the clearance was measured: the clearance
  // now is at least the measured one less this, and at most the measured one plus this.
  const auto travelled_m = [&]() {
    return (pose_.translation() - measured_at_.translation()).norm() +
           half_diagonal_m_ *
               std::abs(mapper::wrap_angle_rad(pose_.theta_rad - measured_at_.theta_rad));
  };
  if (clearance_known_) {
    const double travelled = travelled_m();
    if (clearance_m_ - travelled - step_reach_m > kSkipMarginM) return true;
    // Too near to skip: measuring again only pays once the body has moved on a little.
    if (travelled < kRemeasureAfterM) return false;
  }
  measured_at_ = pose_;
  clearance_m_ = clearance_m();
  clearance_known_ = true;
  return clearance_m_ - step_reach_m > kSkipMarginM;
}

const mapper::Pose2& PhysicsWorld::step(const BodyTwist& twist, double dt_s) {
  const double ds_m = twist.v_mps * dt_s;
  const double dtheta_rad = twist.w_radps * dt_s;
  const mapper::Pose2 free_pose = advance_pose(pose_, ds_m, dtheta_rad);
  // Box2D integrates a straight chord; aiming it at the arc's mid heading makes its free
  // motion agree with the arc to second order, so contact and truth hand over smoothly.
  const double chord_heading = pose_.theta_rad + 0.5 * dtheta_rad;
  body_->SetTransform(to_b2(pose_.translation()), static_cast<float>(pose_.theta_rad));
  body_->SetLinearVelocity({static_cast<float>(twist.v_mps * std::cos(chord_heading)),
                            static_cast<float>(twist.v_mps * std::sin(chord_heading))});
  body_->SetAngularVelocity(static_cast<float>(twist.w_radps));
  const double step_reach_m = std::abs(ds_m) + half_diagonal_m_ * std::abs(dtheta_rad);
  if (options_.skip_free_steps && clear_of_obstacles(step_reach_m)) {
    // Nothing within reach: the step would move the body freely, and its pose is the free one
    // anyway (and the next step sets the body there). Skipping Box2D here saves its broad
    // phase, solver and per-step timers for most of a run.
    in_contact_ = false;
    pose_ = free_pose;
    ++skipped_steps_;
    return pose_;
  }
  world_->Step(static_cast<float>(dt_s), options_.velocity_iterations,
               options_.position_iterations);

  in_contact_ = false;
  for (b2ContactEdge* edge = body_->GetContactList(); edge != nullptr; edge = edge->next) {
    if (edge->contact->IsTouching()) {
      in_contact_ = true;
      break;
    }
  }
  if (in_contact_) {
    const b2Vec2 p = body_->GetPosition();
    pose_ = {p.x, p.y, mapper::wrap_angle_rad(body_->GetAngle())};
  } else {
    pose_ = free_pose;
  }
  return pose_;
}

}  // namespace cogmap::sim
