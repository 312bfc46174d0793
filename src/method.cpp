#include "roughroll/method.hpp"

#include "roughroll/error.hpp"

namespace roughroll {

std::string to_string(method m) { return m == method::paper ? "paper" : "product"; }

int default_nodes(method m) { return m == method::paper ? 200 : 96; }

method method_from_string(const std::string& name) {
    if (name == "paper") return method::paper;
    if (name == "product") return method::product;
    throw input_error("unknown method '" + name + "' (known: paper, product)");
}

}  // namespace roughroll
