#include "interp/scope.hpp"

namespace lumen::interp {

SymbolTable::SymbolTable() : frames_(1) {}

void SymbolTable::push() { frames_.emplace_back(); }

void SymbolTable::pop() {
    if (frames_.size() > 1) frames_.pop_back();
}

size_t SymbolTable::frame_of(const std::string& name) const {
    for (size_t i = frames_.size(); i-- > 0;)
        if (frames_[i].count(name)) return i;
    return npos;
}

Value* SymbolTable::find(const std::string& name) {
    size_t f = frame_of(name);
    if (f == npos) return nullptr;
    return &frames_[f].find(name)->second;
}

void SymbolTable::declare(const std::string& name, Value v) {
    size_t f = frame_of(name);
    set_in_frame(f == npos ? 0 : f, name, std::move(v));
}

void SymbolTable::local(const std::string& name, Value v) {
    set_in_frame(frames_.size() - 1, name, std::move(v));
}

void SymbolTable::set_in_frame(size_t frame, const std::string& name, Value v) {
    frames_.at(frame)[name] = std::move(v);
}

bool SymbolTable::undef(const std::string& name) {
    size_t f = frame_of(name);
    if (f == npos) return false;
    frames_[f].erase(name);
    return true;
}

std::vector<std::string> SymbolTable::visible_names() const {
    std::vector<std::string> out;
    for (const auto& frame : frames_)
        for (const auto& [name, value] : frame) out.push_back(name);
    return out;
}

}  // namespace lumen::interp
