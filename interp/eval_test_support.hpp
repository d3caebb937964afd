// Shared fixture for the evaluator's unit tests (interp/eval_*_test.cpp): runs SDL text through
// the parser and an Evaluator, without building a whole scene.
#pragma once
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "interp/conversions.hpp"
#include "interp/evaluator.hpp"
#include "parser/parser.hpp"

namespace lumen::interp::testing {

class EvalTest : public ::testing::Test {
protected:
    SourceManager sources;
    InterpOptions options;
    std::vector<Diagnostic> messages;  // warnings and #debug notes
    std::unique_ptr<Evaluator> ev;

    Evaluator& evaluator() {
        if (!ev) ev = std::make_unique<Evaluator>(sources, options, [this](const Diagnostic& d) { messages.push_back(d); });
        return *ev;
    }

    // Runs `text` as a file (named test.pov) and returns its top-level items.
    std::vector<Item> run(const std::string& text, const std::string& name = "test.pov") {
        const SourceFile* file = sources.add(name, text);
        trees_.push_back(parser::parse_file(*file));
        std::vector<Item> items;
        evaluator().run_main(*trees_.back(), *file, [&](const Item& it) { items.push_back(it); });
        return items;
    }

    // Evaluates one expression (after whatever `run` defined).
    Value value(const std::string& expr) {
        const SourceFile* file = sources.add("expr", expr);
        trees_.push_back(parser::parse_expression(*file));
        return evaluator().eval(*trees_.back());
    }
    double number(const std::string& expr) { return to_float(value(expr)); }
    std::vector<double> vec(const std::string& expr) { return components(value(expr)); }
    std::string str(const std::string& expr) { return to_string_value(value(expr)); }
    // The variable `name` after `run`.
    Value var(const std::string& name) {
        Value* v = evaluator().symbols.find(name);
        if (!v) throw std::runtime_error("not declared: " + name);
        return *v;
    }
    double num_var(const std::string& name) { return to_float(var(name)); }

    // The first line of the diagnostic `run(text)` throws ("" if it runs).
    std::string error_of(const std::string& text) {
        try {
            run(text);
        } catch (const LumenError& e) {
            return format_headline(e.diag);
        }
        return "";
    }
    std::string expr_error(const std::string& expr) {
        try {
            value(expr);
        } catch (const LumenError& e) {
            return format_headline(e.diag);
        }
        return "";
    }
    // The text of the #debug messages so far, concatenated.
    std::string debug_output() const {
        std::string s;
        for (const Diagnostic& d : messages)
            if (d.severity == Severity::Note) s += d.message;
        return s;
    }

private:
    std::vector<ast::NodePtr> trees_;
};

}  // namespace lumen::interp::testing
