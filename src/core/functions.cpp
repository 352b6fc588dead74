// *CURVE and *FUNCTION storage: registration, cross-reference resolution, evaluation.
#include "abut/core/functions.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "core/expression.hpp"

namespace abut {

double Curve::value(double at) const {
  if (x.empty()) throw std::logic_error("Curve::value on a curve without points");
  if (at <= x.front()) return y.front();
  if (at >= x.back()) return y.back();
  if (std::isnan(at)) return at;
  // x[i-1] < at < x[i]; linear interpolation between the two points.
  const auto i = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), at) - x.begin());
  const double s = (at - x[i - 1]) / (x[i] - x[i - 1]);
  return y[i - 1] + s * (y[i] - y[i - 1]);
}

namespace {

struct Entry {
  std::int64_t id = 0;
  SourceLocation where;
  bool is_curve = false;
  Curve curve;
  expression::Program program;
};

std::string describe(const SourceLocation& w) {
  std::string s = w.file.empty() ? std::string("the input") : w.file;
  if (w.line > 0) s += ":" + std::to_string(w.line);
  return s;
}

std::string kind_name(const Entry& e) { return e.is_curve ? "*CURVE" : "*FUNCTION"; }

}  // namespace

struct FunctionTable::Impl {
  std::vector<Entry> entries;
  std::unordered_map<std::int64_t, std::int32_t> index_of;

  void add(Entry entry) {
    if (const auto found = index_of.find(entry.id); found != index_of.end()) {
      const Entry& first = entries[static_cast<std::size_t>(found->second)];
      throw InputError(entry.where, "id " + std::to_string(entry.id) + " is already used by the " +
                                        kind_name(first) + " at " + describe(first.where) +
                                        "; *CURVE and *FUNCTION ids share one space");
    }
    index_of.emplace(entry.id, static_cast<std::int32_t>(entries.size()));
    entries.push_back(std::move(entry));
  }

  const Entry& entry(FunctionRef ref) const {
    if (!ref.valid() || static_cast<std::size_t>(ref.index) >= entries.size()) {
      throw std::invalid_argument("invalid FunctionRef " + std::to_string(ref.index));
    }
    return entries[static_cast<std::size_t>(ref.index)];
  }

  const Entry* lookup(std::int64_t id) const {
    const auto found = index_of.find(id);
    return found == index_of.end() ? nullptr : &entries[static_cast<std::size_t>(found->second)];
  }

  // Depth-first search for a cycle of fcn()/crv() calls through entry `i`.
  // state: 0 unvisited, 1 on the current path, 2 finished. `path` holds the current chain.
  void find_cycle(std::size_t i, std::vector<int>& state, std::vector<std::size_t>& path) const {
    state[i] = 1;
    path.push_back(i);
    for (const expression::Reference& r : entries[i].program.references) {
      const auto j = static_cast<std::size_t>(r.target);
      if (state[j] == 1) {
        std::string chain;
        const auto start = std::find(path.begin(), path.end(), j);
        for (auto k = start; k != path.end(); ++k)
          chain += "fcn(" + std::to_string(entries[*k].id) + ") -> ";
        chain += "fcn(" + std::to_string(entries[j].id) + ")";
        throw InputError(entries[j].where, "*FUNCTION " + std::to_string(entries[j].id) +
                                               " calls itself recursively: " + chain);
      }
      if (state[j] == 0) find_cycle(j, state, path);
    }
    path.pop_back();
    state[i] = 2;
  }

  bool uses(std::size_t i, const std::string& variable, std::vector<bool>& visited) const {
    const Entry& e = entries[i];
    if (e.is_curve || visited[i]) return false;
    visited[i] = true;
    for (const expression::NameUse& use : e.program.names)
      if (use.name == variable) return true;
    for (const expression::Reference& r : e.program.references) {
      const auto found = index_of.find(r.id);
      if (found != index_of.end() &&
          uses(static_cast<std::size_t>(found->second), variable, visited)) {
        return true;
      }
    }
    return false;
  }
};

FunctionTable::FunctionTable() : impl_(std::make_unique<Impl>()) {}
FunctionTable::~FunctionTable() = default;
FunctionTable::FunctionTable(FunctionTable&&) noexcept = default;
FunctionTable& FunctionTable::operator=(FunctionTable&&) noexcept = default;

void FunctionTable::add_curve(std::int64_t id, Curve curve, const SourceLocation& where) {
  if (curve.x.size() != curve.y.size()) {
    throw InputError(where, "*CURVE " + std::to_string(id) + " has " +
                                std::to_string(curve.x.size()) + " abscissas but " +
                                std::to_string(curve.y.size()) + " ordinates");
  }
  if (curve.x.empty()) {
    throw InputError(where, "*CURVE " + std::to_string(id) + " has no points; give x, y pairs");
  }
  for (std::size_t i = 0; i < curve.x.size(); ++i) {
    if (!std::isfinite(curve.x[i]) || !std::isfinite(curve.y[i])) {
      throw InputError(where, "*CURVE " + std::to_string(id) + ": point " + std::to_string(i + 1) +
                                  " is not a finite number");
    }
    if (i > 0 && !(curve.x[i] > curve.x[i - 1])) {
      throw InputError(where, "*CURVE " + std::to_string(id) + ": abscissas must increase " +
                                  "strictly, but point " + std::to_string(i + 1) +
                                  " has x = " + std::to_string(curve.x[i]) +
                                  " after x = " + std::to_string(curve.x[i - 1]));
    }
  }
  impl_->add(Entry{id, where, true, std::move(curve), {}});
}

void FunctionTable::add_function(std::int64_t id, const std::string& expression,
                                 const SourceLocation& where) {
  expression::Program program;
  try {
    program = expression::compile(expression);
  } catch (const InputError& e) {
    throw InputError(where, "*FUNCTION " + std::to_string(id) + ": " + e.message());
  }
  impl_->add(Entry{id, where, false, {}, std::move(program)});
}

void FunctionTable::resolve() {
  std::vector<Entry>& entries = impl_->entries;
  for (Entry& e : entries) {
    for (expression::Reference& r : e.program.references) {
      const char* call = r.kind == expression::Reference::Kind::Curve ? "crv" : "fcn";
      const Entry* target = impl_->lookup(r.id);
      const std::string what = std::string(call) + "(" + std::to_string(r.id) + ", ...)";
      if (target == nullptr) {
        throw InputError(
            e.where, expression::describe_at(e.program.text, r.column,
                                             "*FUNCTION " + std::to_string(e.id) + " calls " +
                                                 what + " but there is no *CURVE or *FUNCTION " +
                                                 std::to_string(r.id)));
      }
      // crv() reads a tabulated curve; fcn() accepts a function or a curve (evaluated at t).
      if (r.kind == expression::Reference::Kind::Curve && !target->is_curve) {
        throw InputError(e.where, expression::describe_at(
                                      e.program.text, r.column,
                                      "*FUNCTION " + std::to_string(e.id) + " calls " + what +
                                          " but " + std::to_string(r.id) + " is the *FUNCTION at " +
                                          describe(target->where) + "; use fcn(" +
                                          std::to_string(r.id) + ", x) for a function"));
      }
      r.target = impl_->index_of.at(r.id);
    }
  }
  std::vector<int> state(entries.size(), 0);
  std::vector<std::size_t> path;
  for (std::size_t i = 0; i < entries.size(); ++i)
    if (state[i] == 0) impl_->find_cycle(i, state, path);
}

bool FunctionTable::contains(std::int64_t id) const { return impl_->lookup(id) != nullptr; }

FunctionRef FunctionTable::find(std::int64_t id, const SourceLocation& where) const {
  const auto found = impl_->index_of.find(id);
  if (found == impl_->index_of.end()) {
    throw InputError(where, "there is no *CURVE or *FUNCTION with id " + std::to_string(id));
  }
  return FunctionRef{found->second};
}

bool FunctionTable::is_curve(FunctionRef ref) const { return impl_->entry(ref).is_curve; }

std::span<const double> FunctionTable::breakpoints(FunctionRef ref) const {
  const Entry& e = impl_->entry(ref);
  return e.is_curve ? std::span<const double>(e.curve.x) : std::span<const double>();
}

bool FunctionTable::uses(FunctionRef ref, const std::string& variable) const {
  impl_->entry(ref);  // checks the handle
  std::vector<bool> visited(impl_->entries.size(), false);
  return impl_->uses(static_cast<std::size_t>(ref.index), variable, visited);
}

double FunctionTable::value(FunctionRef ref, double abscissa, const Variables& vars) const {
  const Entry& e = impl_->entry(ref);
  return e.is_curve ? e.curve.value(abscissa) : expression::evaluate(e.program, vars, this);
}

double evaluate_constant_expression(const std::string& expression) {
  const expression::Program program = expression::compile(expression);
  if (!program.names.empty()) {
    const expression::NameUse& use = program.names.front();
    throw InputError(expression::describe_at(
        expression, use.column,
        "'" + use.name +
            "' is a variable, but a constant expression may only use numbers, pi "
            "and functions of them"));
  }
  if (!program.references.empty()) {
    throw InputError(
        expression::describe_at(expression, program.references.front().column,
                                "crv() and fcn() cannot be used in a constant expression"));
  }
  return expression::evaluate(program, Variables{}, nullptr);
}

}  // namespace abut
