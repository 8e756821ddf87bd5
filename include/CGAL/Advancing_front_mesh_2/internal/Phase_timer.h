// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_PHASE_TIMER_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_PHASE_TIMER_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/Statistics.h>

#include <boost/config.hpp>

#include <array>
#include <chrono>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// The phases of `Phase_times`, which partition the meshing time.
enum Phase { FRONT_SELECTION, CLOSE_POINT_SEARCH, DELAUNAY_CLOSURE, PLACEMENT, CIRCLE_OCTREE,
             CAVITY, VISIBILITY, FRONT_UPDATE, OUTPUT, NUMBER_OF_PHASES };

// Charges the time between phase changes to the current phase, when
// enabled (reading the clock at every change costs a few percent). The
// timer is mutable through const references: const queries have phases too.
class Phase_timer
{
  typedef std::chrono::steady_clock Clock;

public:
  void set_enabled(bool on) { enabled_ = on; }
  bool enabled() const { return enabled_; }

  // Zeroes the times.
  void clear() const
  {
    seconds_.fill(0);
    start_ = Clock::now();
  }

  // Zeroes the times and starts charging `p`.
  void restart(Phase p) const
  {
    clear();
    phase_ = p;
  }

  // Charges the time since the last change to the current phase and makes
  // `p` current; returns the phase it replaces.
  //
  // The clock is read out of line: the mesher enters a phase some twenty
  // times a step, mostly with timing off, and with the clock's code inline
  // the compiler called enter() instead of inlining it (1.4% of a run's
  // instructions with timing off).
  Phase enter(Phase p) const
  {
    const Phase previous = phase_;
    if(enabled_) charge(previous);
    phase_ = p;
    return previous;
  }

  void store(Phase_times& t) const
  {
    t.front_selection = seconds_[FRONT_SELECTION];
    t.close_point_search = seconds_[CLOSE_POINT_SEARCH];
    t.delaunay_closure = seconds_[DELAUNAY_CLOSURE];
    t.placement = seconds_[PLACEMENT];
    t.circle_octree = seconds_[CIRCLE_OCTREE];
    t.cavity = seconds_[CAVITY];
    t.visibility = seconds_[VISIBILITY];
    t.front_update = seconds_[FRONT_UPDATE];
    t.output = seconds_[OUTPUT];
  }

  // The phase of a scope; the enclosing phase resumes when it ends.
  class Scope
  {
  public:
    Scope(const Phase_timer& t, Phase p) : t_(t), previous_(t.enter(p)) {}
    ~Scope() { t_.enter(previous_); }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

  private:
    const Phase_timer& t_;
    Phase previous_;
  };

private:
  BOOST_NOINLINE void charge(Phase p) const
  {
    const Clock::time_point now = Clock::now();
    seconds_[p] += std::chrono::duration<double>(now - start_).count();
    start_ = now;
  }

  bool enabled_ = false;
  mutable Phase phase_ = FRONT_SELECTION;
  mutable Clock::time_point start_;
  mutable std::array<double, NUMBER_OF_PHASES> seconds_ = {{0, 0, 0, 0, 0, 0, 0, 0, 0}};
};

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_PHASE_TIMER_H
