#include "interp/literal_items.hpp"

namespace lumen::interp {

Item literal_item(const ast::LiteralRun& run, size_t i, size_t offset, const SourceFile* file) {
    Item it;
    it.loc = run.loc(file, i);
    const size_t size = run.sizes[i];
    if (size == 0) {
        it.kind = Item::Kind::Comma;
    } else if (size == 1) {
        it.value = Value{run.values[offset], it.loc};
    } else {
        VecN v;
        v.c.assign(run.values.begin() + std::ptrdiff_t(offset),
                   run.values.begin() + std::ptrdiff_t(offset + size));
        it.value = Value{std::move(v), it.loc};
    }
    return it;
}

void expand_literals(std::vector<Item>& items) {
    bool any = false;
    for (const Item& it : items) any = any || it.kind == Item::Kind::Literals;
    if (!any) return;
    std::vector<Item> out;
    for (Item& it : items) {
        if (it.kind != Item::Kind::Literals) {
            out.push_back(std::move(it));
            continue;
        }
        const ast::LiteralRun& run = *it.literals;
        for (size_t i = 0, offset = 0; i < run.sizes.size(); offset += run.sizes[i++])
            out.push_back(literal_item(run, i, offset, it.loc.file));
    }
    items = std::move(out);
}

}  // namespace lumen::interp
