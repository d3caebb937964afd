#include "cli/options.hpp"

#include <algorithm>
#include <cmath>

namespace lumen::cli {

int resolve_start(std::optional<double> v, int size) {
    if (!v) return 0;
    const int i = (*v >= 0 && *v < 1) ? int(*v * size) : int(std::floor(*v)) - 1;
    return std::clamp(i, 0, size - 1);
}

int resolve_end(std::optional<double> v, int size) {
    if (!v) return size - 1;
    const int i = (*v >= 0 && *v <= 1) ? int(*v * size) - 1 : int(std::floor(*v)) - 1;
    return std::clamp(i, 0, size - 1);
}

render::RenderOptions effective_render_options(const Options& o) {
    render::RenderOptions r = o.render;
    r.start_row = resolve_start(o.start_row, r.height);
    r.end_row = resolve_end(o.end_row, r.height);
    r.start_col = resolve_start(o.start_col, r.width);
    r.end_col = resolve_end(o.end_col, r.width);
    return r;
}

}  // namespace lumen::cli
