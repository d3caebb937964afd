#include "render/radiosity/options.hpp"

namespace lumen::render::radiosity {

const char* method_name(Method m) {
    switch (m) {
        case Method::Auto: return "auto";
        case Method::Matrix: return "matrix";
        case Method::Jacobi: return "jacobi";
        case Method::GaussSeidel: return "gauss_seidel";
        case Method::Progressive: return "progressive";
    }
    return "?";
}

const char* form_factor_name(FormFactorMethod m) {
    switch (m) {
        case FormFactorMethod::RayCast: return "raycast";
        case FormFactorMethod::Analytic: return "analytic";
        case FormFactorMethod::Hemicube: return "hemicube";
    }
    return "?";
}

}  // namespace lumen::render::radiosity
