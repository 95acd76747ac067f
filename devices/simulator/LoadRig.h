// The simulated hands at a calibration rig: the load a calibration wizard
// asks for (a mass hung on the beam's tip, a weight placed on the capacitive
// beam), set on the GUI thread and read by the scenario on the acquisition
// thread. With a real probe the operator places the load; with the
// simulator the wizard places it through this, so both wizards can be
// completed end to end against known physics.
#pragma once

#include <atomic>

namespace tactiscope::devices::simulator {

class LoadRig {
public:
    // The total load now on the sensor, in newtons (0: unloaded).
    void place(double force_n) { m_force_n.store(force_n, std::memory_order_relaxed); }
    double load_n() const { return m_force_n.load(std::memory_order_relaxed); }

private:
    std::atomic<double> m_force_n = 0.0;
};

}  // namespace tactiscope::devices::simulator
