// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/problems/contact.hpp"
#include "roughroll/problems/contact_internals.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"
#include "roughroll/numerics/collocation.hpp"
#include "roughroll/problems/dissimilar_zones.hpp"

#include "contact_impl.hpp"

namespace roughroll {

contact::impl::impl(const roughness& surfaces, double f, const solver_options& options, const dissimilar& materials,
                    normal_cache* cache, std::shared_ptr<level_store> levels)
    : surfaces_(surfaces), options_(options), f_(f), materials_(materials), store_(std::move(levels)) {
    if (!(std::isfinite(f) && f > 0.0)) throw input_error("friction coefficient f must be positive and finite");
    check_dissimilar(materials, options);
    // Richardson's rule holds only where the error already falls like n^-4.
    if (extrapolates(surfaces, options)) check_extrapolation_range(widest_kernel(), options.nodes(), "these kernels");
    const auto make = [&] { return make_point_model(surfaces, f, options, materials, cache); };
    if (store_) {  // the store's model (an aliasing pointer that keeps the store), or else this contact's own
        std::unique_ptr<point_model> own;
        point_model& m = store_->model({surfaces, f, materials, options}, make, own);
        owner_ = own ? std::shared_ptr<point_model>(std::move(own)) : std::shared_ptr<point_model>(store_, &m);
        owner_->share_levels_in(store_.get());
    } else {
        owner_ = make();
    }
    model_ = hold(*owner_);
    if (extrapolates(surfaces, options)) {
        companion_ = level(options.nodes() / 2);
        reported_ = std::make_unique<normal_solution>(model_->normal());
        reported_->lambda = richardson(reported_->lambda, companion_->normal().lambda);
    }
}

contact::contact(const roughness& surfaces, double f, const solver_options& options, const dissimilar& materials,
                 normal_cache* cache)
    : contact(std::make_unique<impl>(surfaces, f, options, materials, cache, nullptr)) {}

contact::contact(std::unique_ptr<impl> state) : impl_(std::move(state)) {}

contact contact_internals::with_levels(const roughness& surfaces, double f, const solver_options& options,
                                       const dissimilar& materials, normal_cache* cache,
                                       std::shared_ptr<level_store> levels) {
    return contact(std::make_unique<contact::impl>(surfaces, f, options, materials, cache, std::move(levels)));
}

contact::contact(contact&&) noexcept = default;
contact& contact::operator=(contact&&) noexcept = default;
contact::~contact() = default;

double contact::friction() const { return impl_->f_; }

const dissimilar& contact::materials() const { return impl_->materials_; }

void contact::set_checkpoint(std::function<void()> hook) {
    impl_->hook_ = hook;  // a model of the store calls the hook at work (level_store.hpp)
    if (!impl_->store_ || !impl_->model_->shared_by_rungs()) impl_->model_->set_checkpoint(std::move(hook));
}

const normal_solution& contact::normal() const { return impl_->normal(); }

const normal_solution& contact::impl::normal() const {
    // At full coupling after a point, level n's coupled pressure, not extrapolated (docs/formulation.md 8(e)).
    return reported_ && !model_->coupling() ? *reported_ : model_->normal();
}

const coupling_summary* contact::coupling() const { return impl_->model_->coupling(); }

tangential_solver& contact_internals::tangential(contact& c) {
    if (tangential_solver* t = c.impl_->model_->tangential()) return *t;
    throw input_error(
        "method 'one-parameter' has no two-parameter tangential solver: use contact::traction and "
        "contact::slip_velocity");
}

std::vector<int> contact::impl::below() {
    std::vector<int> ns;
    if (build_levels())
        for (int i = 0; levels_[i]; ++i) ns.push_back((*levels_[i]).nodes());  // empty: this one
    return ns;
}

tangential_solution contact::point(double Q) {
    return impl_->model_->point(Q, [this] { return impl_->below(); });
}

std::vector<estimate_level> contact_internals::levels_before(contact& c, double Q) {
    return c.impl_->model_->levels_before(Q, [&c] { return c.impl_->below(); });
}

const dissimilar_zones* contact_internals::johnson_zones(contact& c) { return c.impl_->model_->johnson_zones(); }

tangential_solution contact::continued_point(double Q, const tangential_solution& previous) {
    return impl_->model_->continued(Q, previous, [this] { return impl_->below(); });
}

kernel contact::impl::widest_kernel() const {
    const double rate = std::max(kernel::normal(surfaces_).max_rate(), kernel::tangential(surfaces_).max_rate());
    return kernel(std::vector<exponential_term>{{1.0, rate}});
}

tangential_solution contact::distribution(const tangential_solution& s) { return impl_->distribution(s); }

std::optional<error_estimate> contact::estimate(const tangential_solution& s) {
    std::optional<error_estimate> e = impl_->estimate(s);
    if (e && impl_->term_) impl_->term_(s, normal(), coupling(), *e, false);
    return e;
}

void contact::set_estimate_term(estimate_term term) { impl_->term_ = std::move(term); }

contact::swept_point contact::at_stick_end(double c0) {
    swept_point p = impl_->at_stick_end(c0);
    if (p.estimate && impl_->term_) {
        impl_->term_(p.solution, normal(), coupling(), *p.estimate, true);
        impl_->refuse_load_outside(p.solution, p.estimate->Q);  // Q's interval with the term, as without it
    }
    return p;
}

tangential_solution contact_internals::reported_at_stick_end(contact& c, double c0) {
    tangential_solution own;
    std::optional<tangential_solution> coarse;
    return c.impl_->reported_at(c0, own, coarse);
}

std::optional<std::string> contact::beyond_every_n(double Q, int top, double tolerance) const {
    return impl_->model_->beyond_every_n(Q, top, tolerance);
}

double contact::traction(const tangential_solution& d, double r) { return impl_->model_->traction(d, r); }

double contact::slip_velocity(const tangential_solution& d, double r) { return impl_->model_->slip_velocity(d, r); }

std::vector<double> contact::slip_velocity(const tangential_solution& d, const std::vector<double>& r) {
    return impl_->model_->slip_velocity(d, r);
}

std::vector<contact::distribution_row> contact::distributions(const tangential_solution& d,
                                                              const std::vector<double>& grid) {
    const std::vector<double> velocity = slip_velocity(d, grid);
    std::vector<distribution_row> rows(grid.size());
    for (std::size_t i = 0; i < grid.size(); ++i) {
        distribution_row& row = rows[i];
        row.r = grid[i];
        row.p = normal().pressure(row.r);
        row.p1 = traction(d, row.r);
        row.stick = d.sticks(row.r);
        row.v = row.stick ? 0.0 : velocity[i];
        // NaN is the one v that is not a fault: the trailing edge layer's, not resolved (formulation 8(n)).
        const bool unresolved = d.layout.layers_neglected() && std::isnan(row.v);
        if (!std::isfinite(row.p) || !std::isfinite(row.p1) || !(std::isfinite(row.v) || unresolved))
            throw numerical_error("non-finite traction at r = " + shortest(row.r));
    }
    return rows;
}

}  // namespace roughroll
