// The ros2_control-shaped wrapper (hybrid_controller.hpp) driving the UR5 on the sphere: this program
// plays the controller manager and the hardware, the generated plant (ur5_plant.c) standing for the arm
// and its force-torque sensor. Per period: the hardware's read (the plant's joints and the sensor's
// wrench into the state interfaces), the controller's update, the hardware's write (the effort commands
// held over the plant's RK4 steps).
//
// Build (after `python -m hybrid generate --experiment tracing --out . --name ur5`):
//     cc -std=c99 -O2 -c ur5_controller.c ur5_plant.c
//     c++ -std=c++17 -O2 main.cpp ur5_controller.o ur5_plant.o -o ros2_like
// Run:
//     ./ros2_like [--samples N] [--miss K] [--nan K]
// --miss K: the update of period K is skipped (a missed deadline: the next one is late);
// --nan K: the wrench reads NaN in period K.
// Prints a CSV row per period: k, t, updated (0/1), the update's result (OK/ERROR, - when skipped), the
// step's status, then q, qd, the wrench given to the update and the effort commands after it.
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

extern "C" {
#include "ur5_controller.h"
#include "ur5_plant.h"
}
#include "hybrid_controller.hpp"

HYBRID_CONTROLLER_TRAITS(ur5)

namespace {

using Controller = hybrid_ros2_like::HybridController<ur5_traits>;
constexpr std::size_t NQ = Controller::nq;
static_assert(NQ == UR5_PLANT_NQ, "the controller and the plant have the same joints");

// the hardware: its numbers, exported by name (a ros2_control SystemInterface's state and command interfaces)
struct Hardware {
    std::array<double, NQ> position{}, velocity{}, effort{};
    std::array<double, 6> wrench{};
    std::vector<std::string> joints{"shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
                                    "wrist_1_joint",      "wrist_2_joint",       "wrist_3_joint"};
    std::string sensor = "tcp_fts";

    std::vector<hybrid_ros2_like::LoanedStateInterface> states() const {
        std::vector<hybrid_ros2_like::LoanedStateInterface> out;
        const char *axes[6] = {"force.x", "force.y", "force.z", "torque.x", "torque.y", "torque.z"};
        for (std::size_t i = 0; i < 6; ++i) out.emplace_back(sensor + "/" + axes[i], &wrench[i]);
        for (std::size_t i = 0; i < NQ; ++i) {
            out.emplace_back(joints[i] + "/velocity", &velocity[i]);
            out.emplace_back(joints[i] + "/position", &position[i]);
        }
        return out;
    }

    std::vector<hybrid_ros2_like::LoanedCommandInterface> commands() {
        std::vector<hybrid_ros2_like::LoanedCommandInterface> out;
        for (std::size_t i = 0; i < NQ; ++i) out.emplace_back(joints[i] + "/effort", &effort[i]);
        return out;
    }
};

int usage(const char *self) {
    std::fprintf(stderr, "usage: %s [--samples N] [--miss K] [--nan K]\n", self);
    return 2;
}

}  // namespace

int main(int argc, char **argv) {
    long samples = 300, miss = -1, nan_at = -1;
    for (int a = 1; a < argc; ++a) {
        long *target = !std::strcmp(argv[a], "--samples") ? &samples
                     : !std::strcmp(argv[a], "--miss")    ? &miss
                     : !std::strcmp(argv[a], "--nan")     ? &nan_at
                                                          : nullptr;
        if (!target || a + 1 >= argc) return usage(argv[0]);
        char *end = nullptr;
        *target = std::strtol(argv[++a], &end, 10);
        if (*end || *target < 0) return usage(argv[0]);
    }

    ur5_plant plant;
    ur5_plant_init(&plant);
    Hardware hw;
    Controller ctrl;
    if (ctrl.on_init() != hybrid_ros2_like::CallbackReturn::SUCCESS ||
        ctrl.on_configure({hw.joints, hw.sensor}) != hybrid_ros2_like::CallbackReturn::SUCCESS) {
        std::fprintf(stderr, "the controller did not configure\n");
        return 1;
    }
    ctrl.assign_interfaces(hw.commands(), hw.states());
    if (ctrl.on_activate() != hybrid_ros2_like::CallbackReturn::SUCCESS) {
        std::fprintf(stderr, "the controller did not activate: an interface is missing\n");
        return 1;
    }
    const hybrid_ros2_like::Duration period(plant.sample_time);
    for (long k = 0; k < samples; ++k) {
        const double t = static_cast<double>(k) * plant.sample_time;
        // read
        for (std::size_t i = 0; i < NQ; ++i) {
            hw.position[i] = plant.x[i];
            hw.velocity[i] = plant.x[NQ + i];
        }
        ur5_plant_wrench(&plant, hw.wrench.data());
        if (k == nan_at) hw.wrench[0] = std::numeric_limits<double>::quiet_NaN();
        // update
        const bool updated = k != miss;
        const bool ok = updated && ctrl.update(hybrid_ros2_like::Time(t), period) == hybrid_ros2_like::return_type::OK;
        std::printf("%ld,%.17g,%d,%s,%s", k, t, updated ? 1 : 0, !updated ? "-" : ok ? "OK" : "ERROR",
                    updated ? ctrl.last_status_name() : "-");
        for (double v : hw.position) std::printf(",%.17g", v);
        for (double v : hw.velocity) std::printf(",%.17g", v);
        for (double v : hw.wrench) std::printf(",%.17g", v);
        for (double v : hw.effort) std::printf(",%.17g", v);
        std::printf("\n");
        // write: the efforts held over the period
        const int status = ur5_plant_advance(&plant, hw.effort.data(), plant.steps_per_sample);
        if (status != UR5_PLANT_OK) {
            std::fprintf(stderr, "the plant stopped at t = %.4f s: %s\n", t, ur5_plant_status_name(status));
            return 1;
        }
    }
    ctrl.on_deactivate();
    ctrl.release_interfaces();
    return 0;
}
