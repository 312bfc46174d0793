// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughroll/io/micro_geometry_input.hpp"
#include "micro_geometry_table.hpp"

#include <cmath>
#include <vector>

#include "roughroll/base/error.hpp"
#include "roughroll/io/profile_csv.hpp"
#include "roughroll/base/text.hpp"
#include "toml_input.hpp"

namespace roughroll {
namespace {

using namespace toml_input;

const toml::node& required(const toml::table& table, std::string_view key, const std::string& source,
                           const std::string& path) {
    const toml::node* node = table.get(key);
    if (node == nullptr) fail(source, "missing key " + quoted(join(path, key)));
    return *node;
}

// One of `names`, or an error listing them.
template <class Kind, std::size_t N>
Kind choice(const toml::node& node, const std::pair<const char*, Kind> (&names)[N], const std::string& source,
            const std::string& path) {
    const std::string& name = string_at(node, source, path);
    std::string all;
    for (const auto& [text, kind] : names) {
        if (name == text) return kind;
        all += (all.empty() ? "\"" : ", \"") + std::string(text) + "\"";
    }
    fail(source, quoted(path) + " must be one of " + all + " (got \"" + echo(name) + "\")");
}

// An array of numbers (a measured profile's x1 or h0); each element is checked by the profile's
// rules (profile_from_arrays), which name its index.
std::vector<double> numbers_at(const toml::node& node, const std::string& source, const std::string& path) {
    const toml::array* array = node.as_array();
    if (array == nullptr) wrong_type(node, "an array of numbers", source, path);
    std::vector<double> out;
    out.reserve(array->size());
    for (std::size_t i = 0; i < array->size(); ++i)
        out.push_back(number_at(*array->get(i), source, path + "[" + std::to_string(i) + "]"));
    return out;
}

constexpr std::pair<const char*, profile_kind> profile_names[] = {{"flat", profile_kind::flat},
                                                                  {"sine", profile_kind::sine},
                                                                  {"sawtooth", profile_kind::sawtooth},
                                                                  {"measured", profile_kind::measured}};
constexpr std::pair<const char*, micro_shape_kind> shape_names[] = {{"sine", micro_shape_kind::sine}};
constexpr std::pair<const char*, decay_kind> decay_names[] = {
    {"linear", decay_kind::linear}, {"quadratic", decay_kind::quadratic}, {"cosine", decay_kind::cosine}};
constexpr std::pair<const char*, normal_factor> factor_names[] = {{"derived", normal_factor::derived},
                                                                  {"printed", normal_factor::printed}};

}  // namespace

micro_geometry read_micro_geometry(const toml::table& table, const std::string& source, const std::string& path,
                                   const std::filesystem::path& base_dir) {
    check_keys(table,
               {"lambda0", "mu0", "H", "l", "profile", "delta", "profile_csv", "profile_x1", "profile_h0",
                "micro_shape", "decay", "factor_2_12"},
               source, path);
    const auto key = [&path](std::string_view name) { return join(path, name); };
    micro_geometry g;
    g.material.lambda0 =
        bounded_number(required(table, "lambda0", source, path), lower_bound::non_negative, source, key("lambda0"));
    g.material.mu0 = bounded_number(required(table, "mu0", source, path), lower_bound::positive, source, key("mu0"));
    g.material.H = bounded_number(required(table, "H", source, path), lower_bound::positive, source, key("H"));
    g.material.l = bounded_number(required(table, "l", source, path), lower_bound::positive, source, key("l"));
    g.bottom.kind = choice(required(table, "profile", source, path), profile_names, source, key("profile"));
    g.decay = choice(required(table, "decay", source, path), decay_names, source, key("decay"));
    if (const toml::node* shape = table.get("micro_shape"))
        g.shape = choice(*shape, shape_names, source, key("micro_shape"));
    if (const toml::node* factor = table.get("factor_2_12"))
        g.factor_2_12 = choice(*factor, factor_names, source, key("factor_2_12"));

    const bool has_delta = g.bottom.kind == profile_kind::sine || g.bottom.kind == profile_kind::sawtooth;
    const std::string kind = "profile = \"" + std::string(to_string(g.bottom.kind)) + "\"";
    if (has_delta) {
        g.bottom.delta =
            bounded_number(required(table, "delta", source, path), lower_bound::non_negative, source, key("delta"));
        if (!(g.bottom.delta < g.material.H)) {
            fail(source, quoted(key("delta")) + " = " + shortest(g.bottom.delta) + " must be < " + quoted(key("H")) +
                             " = " + shortest(g.material.H) +
                             ": the profile's peak would reach the top of the layer "
                             "(the paper's 0 <= h0 < H)");
        }
    } else if (table.contains("delta")) {
        fail(source, quoted(key("delta")) + " is not used by " + kind + " (only by \"sine\" and \"sawtooth\")");
    }

    const bool has_arrays = table.contains("profile_x1") || table.contains("profile_h0");
    if (g.bottom.kind == profile_kind::measured && has_arrays) {
        // The samples as arrays (Python's NumPy arrays of the CSV's columns): both, and no file.
        if (table.contains("profile_csv"))
            fail(source, "give the measured profile as " + quoted(key("profile_csv")) + " or as " +
                             quoted(key("profile_x1")) + " and " + quoted(key("profile_h0")) + ", not both");
        const std::vector<double> x1 =
            numbers_at(required(table, "profile_x1", source, path), source, key("profile_x1"));
        const std::vector<double> h0 =
            numbers_at(required(table, "profile_h0", source, path), source, key("profile_h0"));
        if (x1.size() != h0.size())
            fail(source, quoted(key("profile_x1")) + " has " + std::to_string(x1.size()) + " samples but " +
                             quoted(key("profile_h0")) + " has " + std::to_string(h0.size()) + ": give one h0 per x1");
        if (x1.size() < static_cast<std::size_t>(min_profile_samples))
            fail(source, "a measured profile needs at least " + std::to_string(min_profile_samples) +
                             " samples over one period: " + quoted(key("profile_x1")) + " has " +
                             std::to_string(x1.size()));
        // Sample i named by its index (from 0), as a CSV's by its line: "<source>: '...profile_x1' and
        // '...profile_h0' at index:3: x1 = ... does not increase".
        const std::string where =
            source + ": " + quoted(key("profile_x1")) + " and " + quoted(key("profile_h0")) + " at index";
        g.bottom.measured = profile_from_arrays(x1, h0, where, g.material.l);
    } else if (g.bottom.kind == profile_kind::measured) {
        const std::string& file = string_at(required(table, "profile_csv", source, path), source, key("profile_csv"));
        if (file.empty()) fail(source, quoted(key("profile_csv")) + " must not be empty");
        const std::filesystem::path csv =
            std::filesystem::path(file).is_absolute() ? std::filesystem::path(file) : base_dir / file;
        try {
            g.bottom.measured = read_profile_csv(csv.string(), g.material.l);
        } catch (const input_error& e) {
            // The CSV's own message names its file and line; the prefix names the spec and key.
            fail(source, quoted(key("profile_csv")) + ": " + e.what());
        }
    } else {
        for (const char* name : {"profile_csv", "profile_x1", "profile_h0"})
            if (table.contains(name))
                fail(source, quoted(key(name)) + " is not used by " + kind + " (only by \"measured\")");
    }
    // The layer's range names neither file nor key by itself: both here, with the keys to change.
    const std::string range = layer_range_violation(g.material);
    if (!range.empty())
        fail(source,
             range + ": check " + quoted(key("H")) + ", " + quoted(key("mu0")) + " and " + quoted(key("lambda0")));
    check_conditions(g);
    return g;
}

micro_geometry parse_roughness_spec(std::string_view text, const std::string& source,
                                    const std::filesystem::path& base_dir) {
    return read_micro_geometry(parse_toml(text, source), source, "", base_dir);
}

micro_geometry read_roughness_spec(const std::string& file) {
    const std::filesystem::path base = std::filesystem::path(file).parent_path();
    return parse_roughness_spec(read_text(file, "roughness spec"), file, base);
}

}  // namespace roughroll
