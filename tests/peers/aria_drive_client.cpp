// A client written against AriaCoda (the community ARIA library), not cogmap: connects to a P2OS
// robot with ARIA's -rh/-rrtp arguments, enables motors and sonar, drives forward at 300 mm/s
// for 3 s and then turns at 30 deg/s for 3 s, and checks through ARIA's own odometry that the
// robot moved (> 500 mm forward, > 45 deg turned) and that sonar ranges arrived.
// Exit 0 ok, 1 the robot did not do it, 3 no connection. Built by tests/peers/aria_client.sh.
#include "Aria/Aria.h"

#include <cmath>
#include <cstdio>

int main(int argc, char** argv) {
  Aria::init();
  ArArgumentParser parser(&argc, argv);
  parser.loadDefaultArguments();
  ArRobot robot;
  ArRobotConnector connector(&parser, &robot);
  if (!connector.connectRobot()) {
    std::fprintf(stderr, "aria_drive_client: could not connect\n");
    Aria::exit(3);
  }
  robot.runAsync(true);
  robot.lock();
  const ArPose start = robot.getPose();
  robot.enableMotors();
  robot.enableSonar();
  robot.setVel(300);
  robot.unlock();
  ArUtil::sleep(3000);
  robot.lock();
  const ArPose moved = robot.getPose();
  robot.setVel(0);
  robot.setRotVel(30);
  robot.unlock();
  ArUtil::sleep(3000);
  robot.lock();
  const ArPose turned = robot.getPose();
  robot.stop();
  int plausible = 0;
  for (int i = 0; i < robot.getNumSonar(); ++i) {
    const int r = robot.getSonarRange(i);
    if (r > 0 && r < 5000) ++plausible;
  }
  const double forward_mm = start.findDistanceTo(moved);
  const double turn_deg = std::fabs(ArMath::subAngle(turned.getTh(), moved.getTh()));
  std::printf(
      "aria_drive_client: %s %s, forward %.0f mm, turned %.1f deg, %d of %d sonar ranges "
      "plausible\n",
      robot.getRobotType(), robot.getRobotSubType(), forward_mm, turn_deg, plausible,
      robot.getNumSonar());
  robot.unlock();
  const bool ok = forward_mm > 500 && turn_deg > 45 && plausible > 0;
  robot.stopRunning();
  robot.waitForRunExit();
  Aria::exit(ok ? 0 : 1);
  return ok ? 0 : 1;
}
