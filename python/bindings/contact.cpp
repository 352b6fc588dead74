// Python's abut.contact: the contact library (abut/contact/interface.hpp) on numpy arrays.
// Nodal arrays arrive as (n, 3) arrays, the layout of abut.Results' points, and are copied into
// the interface's structure-of-arrays buffers (kept between calls): a few microseconds for 10k
// nodes against milliseconds of contact work.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "abut/contact/interface.hpp"
#include "abut/contact/settings_by_name.hpp"
#include "bindings.hpp"

namespace py = pybind11;

namespace abut::python {
namespace {

using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Indices = py::array_t<std::int32_t, py::array::c_style | py::array::forcecast>;

// `value` of length 1 (one for all) or n (one per facet), as n values.
std::vector<double> per_facet(const Doubles& value, std::size_t n, const char* what) {
  const std::size_t size = static_cast<std::size_t>(value.size());
  if (size != 1 && size != n)
    throw py::value_error(std::string(what) + ": one value or one per facet (" + std::to_string(n) +
                          "), not " + std::to_string(size));
  std::vector<double> out(n);
  for (std::size_t f = 0; f < n; ++f) out[f] = value.data()[size == 1 ? 0 : f];
  return out;
}

ContactSurface make_surface(const Indices& facets, const Doubles& part, const Doubles& penalty,
                            const Doubles& thickness, bool shell) {
  if (facets.ndim() != 2 || facets.shape(1) != 4)
    throw py::value_error("facets: an (n, 4) array of node indices (a triangle repeats its last)");
  const auto n = static_cast<std::size_t>(facets.shape(0));
  const std::vector<double> parts = per_facet(part, n, "part");
  const std::vector<double> pfac = per_facet(penalty, n, "penalty");
  const std::vector<double> t = per_facet(thickness, n, "thickness");
  ContactSurface s;
  const auto r = facets.unchecked<2>();
  for (std::size_t f = 0; f < n; ++f) {
    const auto i = static_cast<py::ssize_t>(f);
    const std::array<std::int32_t, 4> nodes{r(i, 0), r(i, 1), r(i, 2), r(i, 3)};
    const auto id = static_cast<std::int64_t>(parts[f]);
    if (shell)
      s.add_shell(nodes, id, pfac[f], t[f]);
    else
      s.add(nodes, id, pfac[f], t[f]);
  }
  return s;
}

// An (n, 3) array's columns into x, y, z.
void split(const Doubles& a, std::size_t n, const char* what, std::vector<double>& x,
           std::vector<double>& y, std::vector<double>& z) {
  if (a.ndim() != 2 || a.shape(1) != 3 || static_cast<std::size_t>(a.shape(0)) != n)
    throw py::value_error(std::string(what) + ": an (n, 3) array with n = " + std::to_string(n) +
                          " nodes");
  const double* p = a.data();
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = p[3 * i];
    y[i] = p[3 * i + 1];
    z[i] = p[3 * i + 2];
  }
}

class Interface {
 public:
  Interface(const ContactSurface& s1, const ContactSurface& s2, const Doubles& mass,
            const Doubles& x, const py::dict& settings, const std::optional<Indices>& secondary)
      : n_(static_cast<std::size_t>(mass.size())),
        x_(n_),
        y_(n_),
        z_(n_),
        vx_(n_),
        vy_(n_),
        vz_(n_),
        fx_(n_),
        fy_(n_),
        fz_(n_) {
    ContactSettings s;
    for (const auto& [name, value] : settings)
      set_by_name(s, py::cast<std::string>(name), py::cast<double>(value));
    split(x, n_, "x", x_, y_, z_);
    std::vector<std::int32_t> nodes;
    if (secondary) nodes.assign(secondary->data(), secondary->data() + secondary->size());
    ContactInput in;
    in.x = x_, in.y = y_, in.z = z_;
    interface_.emplace(std::move(s), s1, s2, std::span<const double>(mass.data(), n_), in, nodes);
  }

  // Adds the contact forces at (x, v) to `forces` (a new zero array when None) and returns it.
  py::array_t<double> apply(const Doubles& x, const Doubles& v, double time, double dt,
                            std::optional<py::array_t<double>> forces) {
    split(x, n_, "x", x_, y_, z_);
    split(v, n_, "v", vx_, vy_, vz_);
    py::array_t<double> out = forces ? *forces : py::array_t<double>({n_, std::size_t{3}});
    if (out.ndim() != 2 || out.shape(1) != 3 || static_cast<std::size_t>(out.shape(0)) != n_ ||
        !(out.flags() & py::array::c_style))
      throw py::value_error("forces: a C-contiguous float64 (n, 3) array with n = " +
                            std::to_string(n_));
    std::fill(fx_.begin(), fx_.end(), 0.0);
    std::fill(fy_.begin(), fy_.end(), 0.0);
    std::fill(fz_.begin(), fz_.end(), 0.0);
    ContactInput in;
    in.x = x_, in.y = y_, in.z = z_, in.vx = vx_, in.vy = vy_, in.vz = vz_;
    in.time = time;
    in.dt = dt;
    ContactForces f{fx_, fy_, fz_, {}, {}};
    {
      const py::gil_scoped_release released;
      const auto start = std::chrono::steady_clock::now();
      interface_->apply(in, f);
      last_apply_seconds_ =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    double* p = out.mutable_data();
    if (!forces) std::fill(p, p + 3 * n_, 0.0);
    for (std::size_t i = 0; i < n_; ++i) {
      p[3 * i] += fx_[i];
      p[3 * i + 1] += fy_[i];
      p[3 * i + 2] += fz_[i];
    }
    return out;
  }

  py::dict stats() const {
    const ContactStats& s = interface_->stats();
    py::dict d;
    d["force"] = py::make_tuple(s.force.x, s.force.y, s.force.z);
    d["normal_force"] = s.normal_force;
    d["tangential_force"] = s.tangential_force;
    d["elastic_energy"] = s.elastic_energy;
    d["damping_energy"] = s.damping_energy;
    d["friction_energy"] = s.friction_energy;
    d["released_energy"] = s.released_energy;
    d["max_penetration"] = s.max_penetration;
    d["active_points"] = s.active_points;
    d["stable_step"] = s.stable_step;
    d["approach_step"] = s.approach_step;
    d["kink_step"] = s.kink_step;
    return d;
  }
  double stable_step() const { return interface_->stats().step_bound(); }
  py::bytes save_state() const {
    const std::vector<char> b = interface_->save_state();
    return {b.data(), b.size()};
  }
  void restore_state(const py::bytes& bytes) {
    const std::string b = bytes;
    interface_->restore_state(std::vector<char>(b.begin(), b.end()));
  }
  std::size_t point_count() const { return interface_->point_count(); }
  double last_apply_seconds() const { return last_apply_seconds_; }

 private:
  std::size_t n_;
  std::vector<double> x_, y_, z_, vx_, vy_, vz_, fx_, fy_, fz_;
  std::optional<ContactInterface> interface_;
  double last_apply_seconds_ = 0.0;
};

}  // namespace

void bind_contact(py::module_& m) {
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ContactSetupError& e) {
      const py::object type = py::module_::import("abut.errors").attr("ContactSetupError");
      const py::object error = type(e.what(), e.setting());
      PyErr_SetObject(type.ptr(), error.ptr());
    }
  });
  py::class_<ContactSurface>(m, "ContactSurface")
      .def(py::init(&make_surface), py::arg("facets"), py::arg("part") = 1.0, py::arg("penalty"),
           py::arg("thickness"), py::arg("shell") = false)
      .def("__len__", &ContactSurface::size);
  py::class_<Interface>(m, "ContactInterface")
      .def(py::init<const ContactSurface&, const ContactSurface&, const Doubles&, const Doubles&,
                    const py::dict&, const std::optional<Indices>&>(),
           py::arg("surface1"), py::arg("surface2"), py::arg("mass"), py::arg("x"),
           py::arg("settings") = py::dict(), py::arg("secondary_nodes") = py::none())
      .def("apply", &Interface::apply, py::arg("x"), py::arg("v"), py::arg("time"), py::arg("dt"),
           py::arg("forces") = py::none())
      .def_property_readonly("stats", &Interface::stats)
      .def_property_readonly("stable_step", &Interface::stable_step)
      .def_property_readonly("point_count", &Interface::point_count)
      .def_property_readonly("last_apply_seconds", &Interface::last_apply_seconds)
      .def("save_state", &Interface::save_state)
      .def("restore_state", &Interface::restore_state, py::arg("state"));
  m.def("setting_names", &setting_names);
}

}  // namespace abut::python
