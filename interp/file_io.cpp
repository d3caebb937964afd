// #fopen, #read, #write and #fclose as POV-Ray 3.7 runs them (measured): writes format floats
// as %g and vectors as "<%g,%g,%g> ", typed writes emit raw integers; reads take comma-separated
// literals and close (undefine) the file at its end. Paths: reads search the working folder,
// then the library paths; writes stay in the working folder and below.
#include "interp/file_io.hpp"

#include <optional>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "interp/conversions.hpp"
#include "interp/evaluator.hpp"
#include "interp/literal_items.hpp"
#include "interp/item_cursor.hpp"

namespace lumen::interp {
namespace fs = std::filesystem;

namespace {

constexpr size_t kMaxReadBytes = size_t(256) << 20;
constexpr size_t kMaxWrittenBytes = size_t(1) << 30;

bool within(const fs::path& p, const fs::path& root) {
    const fs::path rel = p.lexically_relative(root);
    return !rel.empty() && *rel.begin() != ".." && !rel.is_absolute();
}

fs::path normal(const fs::path& p) { return fs::absolute(p).lexically_normal(); }

// Symbolic links resolved, so that a link inside an allowed folder cannot lead out of it.
fs::path resolved(const fs::path& p) {
    std::error_code ec;
    fs::path r = fs::weakly_canonical(fs::absolute(p), ec);
    return ec ? normal(p) : r;
}

// Where a user file may be opened: the working folder, `options.io_folders` and, for reading,
// the include folders. Returns "" when allowed, else the message's explanation.
std::string refusal(const fs::path& p, bool writing, const InterpOptions& options) {
    std::vector<fs::path> roots{fs::current_path()};
    for (const std::string& d : options.io_folders) roots.emplace_back(d);
    if (!writing) {
        for (const std::string& d : options.library_paths) roots.emplace_back(d);
        if (options.default_include_path && !options.system_include_dir.empty())
            roots.emplace_back(options.system_include_dir);
    }
    const fs::path target = resolved(p);
    for (const fs::path& root : roots)
        if (within(target, resolved(root))) return "";
    return std::string("lumen ") + (writing ? "writes" : "reads") +
           " user files only under the working folder, the scene's folder" +
           (writing ? " and the output folder" : ", the output folder and the library paths") +
           "; Permitted_Path=FOLDER allows another";
}

// ---- #read: the literals of a data file ----

struct Reader {
    FileValue& f;

    void skip_space() {
        const std::string& t = f.text;
        while (f.pos < t.size()) {
            if (std::isspace(static_cast<unsigned char>(t[f.pos]))) {
                ++f.pos;
            } else if (t.compare(f.pos, 2, "//") == 0) {
                while (f.pos < t.size() && t[f.pos] != '\n') ++f.pos;
            } else if (t.compare(f.pos, 2, "/*") == 0) {
                const size_t e = t.find("*/", f.pos + 2);
                f.pos = e == std::string::npos ? t.size() : e + 2;
            } else {
                return;
            }
        }
    }
    bool at_end() {
        skip_space();
        return f.pos >= f.text.size();
    }
    char peek() { return at_end() ? '\0' : f.text[f.pos]; }

    std::optional<double> number() {
        skip_space();
        const char* begin = f.text.c_str() + f.pos;
        char* end = nullptr;
        const double v = std::strtod(begin, &end);
        if (end == begin) return std::nullopt;
        f.pos += size_t(end - begin);
        return v;
    }
    std::optional<std::string> string() {
        std::string s;
        ++f.pos;  // the opening quote
        while (f.pos < f.text.size() && f.text[f.pos] != '"') {
            char c = f.text[f.pos++];
            if (c == '\\' && f.pos < f.text.size()) {
                const char e = f.text[f.pos++];
                c = e == 'n' ? '\n' : e == 't' ? '\t' : e == 'r' ? '\r' : e;
            }
            s += c;
        }
        if (f.pos >= f.text.size()) return std::nullopt;
        ++f.pos;
        return s;
    }
    // One literal: a signed float, a <..> vector of 2-5 of them, or a string.
    std::optional<Value> item(SourceLoc loc) {
        const char c = peek();
        if (c == '"') {
            auto s = string();
            if (!s) return std::nullopt;
            return Value{*s, loc};
        }
        if (c == '<') {
            ++f.pos;
            std::vector<double> v;
            while (true) {
                auto x = number();
                if (!x) return std::nullopt;
                v.push_back(*x);
                const char d = peek();
                ++f.pos;
                if (d == '>') break;
                if (d != ',' || v.size() >= 5) return std::nullopt;
            }
            if (v.size() < 2) return std::nullopt;
            if (v.size() == 5) {
                scene::Colour col;
                col.r = v[0], col.g = v[1], col.b = v[2], col.f = v[3], col.t = v[4];
                return Value{col, loc};
            }
            return Value{VecN{v}, loc};
        }
        auto x = number();
        if (!x) return std::nullopt;
        return Value{*x, loc};
    }
    // After an item: a comma is consumed; anything else is one token POV-Ray loses.
    void separator() {
        if (at_end()) return;
        if (peek() == ',') {
            ++f.pos;
            return;
        }
        const char c = peek();
        if (c == '"') {
            (void)string();
        } else if (c == '<' || c == '>') {
            ++f.pos;
        } else if (!number()) {
            ++f.pos;
        }
    }
};

// ---- #write ----

std::string format_g(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

struct IntegerType {
    const char* name;
    int bytes;
    bool is_signed, big_endian;
};
constexpr IntegerType kIntegerTypes[] = {
    {"uint8", 1, false, false},    {"sint8", 1, true, false},     {"uint16le", 2, false, false},
    {"uint16be", 2, false, true},  {"sint16le", 2, true, false},  {"sint16be", 2, true, true},
    {"sint32le", 4, true, false},  {"sint32be", 4, true, true},
};

const IntegerType* integer_type(const std::string& word) {
    for (const IntegerType& t : kIntegerTypes)
        if (word == t.name) return &t;
    return nullptr;
}

// POV-Ray rounds floor(v + 0.5) and clamps to the type's range.
std::string integer_bytes(const IntegerType& t, double v) {
    const double bits = 8.0 * t.bytes;
    const double lo = t.is_signed ? -std::pow(2.0, bits - 1) : 0;
    const double hi = t.is_signed ? std::pow(2.0, bits - 1) - 1 : std::pow(2.0, bits) - 1;
    double r = std::floor(v + 0.5);
    if (!(r >= lo)) r = lo;  // NaN too
    if (r > hi) r = hi;
    const uint32_t u = static_cast<uint32_t>(static_cast<int64_t>(r));
    std::string out;
    for (int i = 0; i < t.bytes; ++i) {
        const int shift = 8 * (t.big_endian ? t.bytes - 1 - i : i);
        out += static_cast<char>((u >> shift) & 0xff);
    }
    return out;
}

// A string raw, a float as %g, a vector as "<%g,%g,%g> " (POV-Ray's trailing space).
void write_value(const Value& v, std::string& out) {
    if (v.is<std::string>()) {
        out += v.as<std::string>();
    } else if (v.is<double>()) {
        out += format_g(v.as<double>());
    } else if (v.is<VecN>()) {
        out += '<';
        const auto& comps = v.as<VecN>().c;
        for (size_t k = 0; k < comps.size(); ++k) out += (k ? "," : "") + format_g(comps[k]);
        out += "> ";
    } else {
        type_error(v, "a string, float or vector");
    }
}

}  // namespace

std::shared_ptr<FileValue> Evaluator::open_file(const ast::Node& n) {
    const Value name_value = eval(*n.children.at(1));
    const std::string& name = to_string_value(name_value);
    const std::string mode = n.children.at(2)->text;
    auto f = std::make_shared<FileValue>();
    f->name = name;
    const fs::path cwd = normal(fs::current_path());
    if (mode == "read") {
        std::vector<fs::path> tries;
        const fs::path given(name);
        tries.push_back(given.is_absolute() ? given : cwd / given);
        if (!given.is_absolute()) {
            for (const std::string& dir : options_.library_paths) tries.push_back(fs::path(dir) / given);
            if (options_.default_include_path && !options_.system_include_dir.empty())
                tries.push_back(fs::path(options_.system_include_dir) / given);
        }
        for (const fs::path& t : tries) {
            std::error_code ec;
            if (fs::is_regular_file(t, ec)) {
                f->path = normal(t).string();
                break;
            }
        }
        if (f->path.empty())
            throw LumenError(name_value.loc, "cannot open user file '" + name + "' (read)");
        if (const std::string why = refusal(f->path, false, options_); !why.empty())
            throw LumenError(name_value.loc,
                             "IO Restrictions prohibit read access to '" + name + "' (" + why + ")");
        std::error_code ec;
        if (fs::file_size(f->path, ec) > kMaxReadBytes)
            throw LumenError(name_value.loc, "user file '" + name + "' is larger than 256 MiB");
        std::ifstream in(f->path, std::ios::binary);
        std::ostringstream ss;
        ss << in.rdbuf();
        f->text = ss.str();
    } else if (mode == "write" || mode == "append") {
        const fs::path p = normal(fs::path(name).is_absolute() ? fs::path(name) : cwd / name);
        if (const std::string why = refusal(p, true, options_); !why.empty())
            throw LumenError(name_value.loc,
                             "IO Restrictions prohibit write access to '" + name + "' (" + why + ")");
        f->writing = true;
        f->path = p.string();
        f->out = std::fopen(f->path.c_str(), mode == "write" ? "wb" : "ab");
        if (!f->out)
            throw LumenError(name_value.loc, "cannot open user file '" + name + "' (" + mode + ")");
    } else {
        throw LumenError(n.children[2]->loc, "expected read, write or append, found '" + mode + "'");
    }
    return f;
}

void Evaluator::close_file(const std::string& id) {
    Value* v = symbols.find(id);
    if (!v || !v->is<std::shared_ptr<FileValue>>()) return;  // POV ignores it (closed at EOF)
    const std::shared_ptr<FileValue> f = v->as<std::shared_ptr<FileValue>>();
    if (f->out) {
        std::fclose(f->out);
        f->out = nullptr;
        // A file the scene wrote may be #included next (strings.inc does): parse it afresh.
        for (auto it = file_cache_.begin(); it != file_cache_.end();) {
            std::error_code ec;
            it = fs::equivalent(it->first, f->path, ec) ? file_cache_.erase(it) : std::next(it);
        }
    }
    symbols.undef(id);
}

std::shared_ptr<FileValue> Evaluator::file_named(const ast::Node& handle, bool writing) {
    Value* v = symbols.find(handle.text);
    if (!v || !v->is<std::shared_ptr<FileValue>>())
        throw LumenError(handle.loc, "'" + handle.text + "' is not an open file identifier");
    auto f = v->as<std::shared_ptr<FileValue>>();
    if (f->writing != writing)
        throw LumenError(handle.loc, "file '" + f->name + "' is open for " +
                                         (f->writing ? "writing" : "reading"));
    return f;
}

void Evaluator::write_file(const ast::Node& n) {
    const std::shared_ptr<FileValue> f = file_named(*n.children.at(0), true);
    std::string out;
    for (size_t i = 1; i < n.children.size(); ++i) {
        const ast::Node& c = *n.children[i];
        if (c.kind == ast::Kind::Keyword) {
            const IntegerType* t = integer_type(c.text);
            if (!t || i + 1 >= n.children.size())
                throw LumenError(c.loc, "unexpected '" + c.text + "' in #write");
            const Value v = eval(*n.children[++i]);
            if (v.is<double>()) out += integer_bytes(*t, v.as<double>());
            else if (v.is<VecN>()) for (double x : v.as<VecN>().c) out += integer_bytes(*t, x);
            else type_error(v, "a float or vector");
            continue;
        }
        if (c.kind >= ast::Kind::Body && c.kind != ast::Kind::Null) {
            // A directive among the values (`#while ... V, #end`): what it leaves is written.
            std::vector<Item> items;
            if (run_item(c, items) == Flow::Break)
                throw LumenError(c.loc, "#break among the values of a #write");
            expand_literals(items);
            for (const Item& it : items) {
                if (it.kind == Item::Kind::Comma) continue;
                if (it.kind != Item::Kind::Value)
                    throw LumenError(it.loc, it.kind == Item::Kind::Keyword
                                                 ? "unexpected '" + it.keyword + "' in #write"
                                                 : std::string("unexpected item in #write"));
                write_value(it.value, out);
            }
            continue;
        }
        std::vector<Value> values;  // `"y" -2.5` is two items, as in macro arguments
        eval_argument(c, values);
        for (const Value& v : values) write_value(v, out);
    }
    f->written += out.size();
    if (f->written > kMaxWrittenBytes)
        throw LumenError(n.loc, "more than 1 GiB written to user file '" + f->name + "'");
    if (std::fwrite(out.data(), 1, out.size(), f->out) != out.size())
        throw LumenError(n.loc, "cannot write to user file '" + f->name + "'");
}

void Evaluator::read_file(const ast::Node& n) {
    const ast::Node& handle = *n.children.at(0);
    const std::shared_ptr<FileValue> f = file_named(handle, false);
    Reader r{*f};
    for (size_t i = 1; i < n.children.size(); ++i) {
        const ast::Node& var = *n.children[i];
        if (var.kind != ast::Kind::Ident)
            throw LumenError(var.loc, "#read needs identifiers to read into");
        if (r.at_end()) {  // nothing left: the file closes, the variable keeps its value
            close_file(handle.text);
            return;
        }
        std::optional<Value> v = r.item(var.loc);
        if (!v)
            throw LumenError(var.loc, "cannot read a float, vector or string from user file '" +
                                          f->name + "'");
        Value* existing = symbols.find(var.text);
        if (existing && !(existing->is<double>() || existing->is<std::string>() ||
                          (existing->is<VecN>() && existing->as<VecN>().c.size() == 3)))
            throw LumenError(var.loc, "#read into '" + var.text + "': expected an undeclared "
                                      "identifier or a float, 3-D vector or string one, found " +
                                      (existing->is<VecN>()
                                           ? "a " + std::to_string(existing->as<VecN>().c.size()) +
                                                 "-component vector"
                                           : describe_value(*existing)));  // as POV refuses
        if (existing) *existing = std::move(*v);
        else symbols.set_in_frame(0, var.text, std::move(*v));  // new names are global
        r.separator();
        if (r.at_end()) {
            close_file(handle.text);
            return;
        }
    }
}

void Evaluator::file_io(const ast::Node& n) {
    if (n.text == "fopen") {
        const ast::Node& id = *n.children.at(0);
        symbols.set_in_frame(0, id.text, Value{open_file(n), id.loc});  // a global identifier
    } else if (n.text == "fclose") {
        close_file(n.children.at(0)->text);
    } else if (n.text == "write") {
        write_file(n);
    } else {
        read_file(n);
    }
}

}  // namespace lumen::interp
