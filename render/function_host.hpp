// What compiled functions ask of the renderer (fn::Host): a pigment function's colour and a
// pattern function's value at a point. Stateless, so one instance serves every thread, and
// the interpreter is handed it for functions called while a scene is parsed.
#pragma once
#include <memory>

#include "function/vm.hpp"

namespace lumen::render {

const fn::Host& function_host();
std::shared_ptr<const fn::Host> shared_function_host();

}  // namespace lumen::render
