// Brute-force models of the mesher's two search concepts, the oracles of the
// tests: AdvancingFrontPointIndex_2 and AdvancingFrontCircleIndex_2 with a
// linear scan of everything they hold in every query. They answer in the
// order of ids (items), are as simple as possible to be trusted, and cannot
// be saved (a mesher using them refuses checkpoints).
#ifndef AFM_BRUTE_FORCE_INDICES_H
#define AFM_BRUTE_FORCE_INDICES_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <vector>

namespace afm_test {

class Brute_force_point_index
{
  struct Point
  {
    double x = 0, y = 0, reach = 0;
    bool present = false;
  };

public:
  void reset(double, double, double, double, std::size_t = 0) { clear(); }
  void clear()
  {
    points_.clear();
    size_ = 0;
  }
  bool contains(std::size_t id) const { return id < points_.size() && points_[id].present; }
  std::size_t size() const { return size_; }

  void insert(std::size_t id, double x, double y)
  {
    if(id >= points_.size()) points_.resize(id + 1);
    if(points_[id].present) return;
    points_[id] = Point{x, y, 0., true};
    ++size_;
  }
  void remove(std::size_t id)
  {
    if(!contains(id)) return;
    points_[id].present = false;
    --size_;
  }
  void set_reach(std::size_t id, double reach)
  {
    if(!contains(id)) throw std::logic_error("Brute_force_point_index: reach of an absent point");
    points_[id].reach = std::isnan(reach) ? std::numeric_limits<double>::infinity() : reach;
  }
  double reach(std::size_t id) const
  {
    if(!contains(id)) throw std::logic_error("Brute_force_point_index: reach of an absent point");
    return points_[id].reach;
  }

  template <class Function>
  void query_with_reach(double x, double y, double radius, Function f) const
  {
    const double pad = 1e-12 * (std::abs(x) + std::abs(y));
    for(std::size_t id = 0; id < points_.size(); ++id) {
      const Point& p = points_[id];
      if(!p.present) continue;
      const double dx = p.x - x, dy = p.y - y, d2 = dx * dx + dy * dy;
      const double own_pad = pad + 1e-12 * (std::abs(p.x) + std::abs(p.y));
      const double r = radius * (1 + 1e-9) + own_pad;
      if(d2 <= r * r || !std::isfinite(d2)) {
        f(id, p.x, p.y, true);
        continue;
      }
      const double reach = (radius + p.reach) * (1 + 1e-9) + own_pad;
      if(d2 <= reach * reach) f(id, p.x, p.y, false);
    }
  }

  template <class Id_map>
  void renumber(const Id_map& new_id)
  {
    std::vector<Point> renamed;
    for(std::size_t id = 0; id < points_.size(); ++id) {
      if(!points_[id].present) continue;
      const std::size_t n = new_id[id];
      if(n >= renamed.size()) renamed.resize(n + 1);
      renamed[n] = points_[id];
    }
    points_.swap(renamed);
  }

private:
  std::vector<Point> points_;
  std::size_t size_ = 0;
};

template <class Payload_ = std::size_t>
class Brute_force_circle_index
{
public:
  typedef Payload_ Payload;
  typedef std::size_t Item_id;
  template <class P>
  struct Rebind_payload
  {
    typedef Brute_force_circle_index<P> Other;
  };

  void reset(double xmin, double ymin, double xmax, double ymax, double rmax, std::size_t = 0)
  {
    items_.clear();
    free_.clear();
    size_ = 0;
    magnitude_ = (std::max)({std::abs(xmin), std::abs(ymin), std::abs(xmax), std::abs(ymax), rmax});
  }
  std::size_t size() const { return size_; }

  Item_id insert(double cx, double cy, double r, const Payload& p)
  {
    Item_id id;
    if(!free_.empty()) {
      id = free_.back();
      free_.pop_back();
    } else {
      id = items_.size();
      items_.emplace_back();
    }
    items_[id] = Item{cx, cy, r, p, true};
    ++size_;
    return id;
  }
  void remove(Item_id id)
  {
    if(!is_alive(id)) throw std::logic_error("Brute_force_circle_index: removal of a dead item");
    items_[id].alive = false;
    free_.push_back(id);
    --size_;
  }
  bool is_alive(Item_id id) const { return id < items_.size() && items_[id].alive; }
  const Payload& payload(Item_id id) const { return items_[id].payload; }

  template <class Function>
  void query(double qx, double qy, double inflate, Function f) const
  {
    const double pad = 1e-12 * (magnitude_ + std::abs(qx) + std::abs(qy));
    for(const Item& it : items_) {
      if(!it.alive) continue;
      const double dx = it.x - qx, dy = it.y - qy;
      const double reach = (it.r + inflate) * (1 + 1e-9) + pad;
      if(!(dx * dx + dy * dy <= reach * reach) && std::isfinite(dx * dx + dy * dy) && std::isfinite(reach)) continue;
      f(it.payload);
    }
  }

  template <class Function>
  void for_each_payload(Function f) const
  {
    for(const Item& it : items_)
      if(it.alive) f(it.payload);
  }

  bool is_sparse() const { return items_.size() >= 256 && 4 * size_ < items_.size(); }

  template <class Renamed>
  void rebuild(Renamed renamed)
  {
    std::vector<Item> live;
    for(const Item& it : items_)
      if(it.alive) live.push_back(it);
    items_.clear();
    free_.clear();
    size_ = 0;
    for(const Item& it : live) renamed(it.payload, insert(it.x, it.y, it.r, it.payload));
  }

  void shrink_to_fit() { items_.shrink_to_fit(); }

private:
  struct Item
  {
    double x, y, r;
    Payload payload;
    bool alive;
  };
  std::vector<Item> items_;
  std::vector<Item_id> free_;
  std::size_t size_ = 0;
  double magnitude_ = 0;
};

} // namespace afm_test

#endif // AFM_BRUTE_FORCE_INDICES_H
