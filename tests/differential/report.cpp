#include "tests/differential/report.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace lumen::differential {
namespace {

namespace fs = std::filesystem;

// One "key=value" per line; values never contain newlines (messages are flattened).
std::string flatten(std::string s) {
    std::replace(s.begin(), s.end(), '\n', ' ');
    return s;
}

void save(const fs::path& p, const Result& r) {
    std::ofstream out(p);
    out << "name=" << r.name << "\nscene=" << r.scene << "\noptions=" << r.options
        << "\nreference=" << r.reference_image << "\nlumen=" << r.lumen_image
        << "\nheat=" << r.heat_map << "\nmin_psnr=" << r.min_psnr << "\npsnr=" << r.psnr
        << "\nmax_error=" << r.max_error << "\ndiffering=" << r.differing_fraction
        << "\nlumen_s=" << r.lumen_seconds << "\npovray_s=" << r.povray_seconds
        << "\npassed=" << r.passed << "\nmessage=" << flatten(r.message) << "\n";
}

Result load(const fs::path& p) {
    std::map<std::string, std::string> kv;
    std::ifstream in(p);
    for (std::string line; std::getline(in, line);) {
        const size_t eq = line.find('=');
        if (eq != std::string::npos) kv[line.substr(0, eq)] = line.substr(eq + 1);
    }
    const auto num = [&](const char* k) { return std::strtod(kv[k].c_str(), nullptr); };
    Result r;
    r.name = kv["name"];
    r.scene = kv["scene"];
    r.options = kv["options"];
    r.reference_image = kv["reference"];
    r.lumen_image = kv["lumen"];
    r.heat_map = kv["heat"];
    r.min_psnr = num("min_psnr");
    r.psnr = num("psnr");
    r.max_error = int(num("max_error"));
    r.differing_fraction = num("differing");
    r.lumen_seconds = num("lumen_s");
    r.povray_seconds = num("povray_s");
    r.passed = kv["passed"] == "1";
    r.message = kv["message"];
    return r;
}

std::string html_escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '&': out += "&amp;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

std::string fixed(double v, int digits) {
    if (std::isinf(v)) return "identical";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

std::string image_cell(const std::string& src) {
    if (src.empty()) return "<td>-</td>";
    return "<td><a href=\"" + html_escape(src) + "\"><img src=\"" + html_escape(src) +
           "\" loading=\"lazy\"></a></td>";
}

void write_index(const fs::path& out_dir, const std::vector<std::string>& listed) {
    std::vector<Result> results;
    for (const std::string& name : listed) {
        const fs::path p = out_dir / "results" / (name + ".txt");
        if (fs::exists(p)) results.push_back(load(p));
    }
    std::sort(results.begin(), results.end(),
              [](const Result& a, const Result& b) { return a.name < b.name; });
    const size_t passed = size_t(std::count_if(results.begin(), results.end(),
                                               [](const Result& r) { return r.passed; }));
    std::ostringstream html;
    html << "<!doctype html>\n<html><head><meta charset=\"utf-8\"><title>lumen vs POV-Ray</title>\n"
         << "<style>body{font-family:sans-serif}table{border-collapse:collapse}"
         << "td,th{border:1px solid #ccc;padding:4px;vertical-align:top}"
         << "img{max-width:240px}.fail{background:#fdd}.pass{background:#dfd}</style>\n"
         << "</head><body>\n<h1>lumen vs POV-Ray 3.7</h1>\n<p>" << passed << " of "
         << results.size() << " scenes reach their PSNR floor. Heat map: black = equal, red "
         << "to yellow to white = up to 64 levels or more.</p>\n<table>\n<tr><th>scene</th>"
         << "<th>POV-Ray</th><th>lumen</th><th>difference</th><th>PSNR (floor)</th>"
         << "<th>max error</th><th>pixels differing</th><th>lumen time</th>"
         << "<th>POV-Ray time</th></tr>\n";
    for (const Result& r : results) {
        html << "<tr class=\"" << (r.passed ? "pass" : "fail") << "\"><td><b>"
             << html_escape(r.name) << "</b><br>" << html_escape(r.scene) << "<br><code>"
             << html_escape(r.options) << "</code>";
        if (!r.message.empty()) html << "<br><pre>" << html_escape(r.message) << "</pre>";
        html << "</td>" << image_cell(r.reference_image) << image_cell(r.lumen_image)
             << image_cell(r.heat_map) << "<td>" << fixed(r.psnr, 2) << " dB<br>(&ge; "
             << fixed(r.min_psnr, 0) << ")</td><td>" << r.max_error << "</td><td>"
             << fixed(100 * r.differing_fraction, 2) << " %</td><td>" << fixed(r.lumen_seconds, 2)
             << " s</td><td>" << fixed(r.povray_seconds, 2) << " s</td></tr>\n";
    }
    html << "</table>\n</body></html>\n";
    const fs::path tmp = out_dir / ("index.html.tmp" + std::to_string(getpid()));
    std::ofstream(tmp) << html.str();
    fs::rename(tmp, out_dir / "index.html");
}

}  // namespace

void record_result(const std::string& out_dir, const Result& r,
                   const std::vector<std::string>& listed) {
    const fs::path dir = fs::path(out_dir) / "results";
    fs::create_directories(dir);
    const fs::path tmp = dir / (r.name + ".tmp");
    save(tmp, r);
    fs::rename(tmp, dir / (r.name + ".txt"));
    write_index(out_dir, listed);
}

}  // namespace lumen::differential
