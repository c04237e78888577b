#include "tests/support/vcd_reader.h"

#include <fstream>

namespace testsupport {

namespace {

std::string without_leading_zeros(const std::string& bits) {
    const size_t first = bits.find_first_not_of('0');
    return first == std::string::npos ? "0" : bits.substr(first);
}

// The header up to $enddefinitions: scopes and declarations.
void read_header(std::ifstream& in, vcd_file* v) {
    std::vector<std::string> scope;
    std::string token;
    while (in >> token) {
        if (token == "$timescale") {
            std::string t;
            while (in >> t && t != "$end") v->timescale += t;
        } else if (token == "$scope") {
            std::string kind, name, end;
            in >> kind >> name >> end;
            scope.push_back(name);
        } else if (token == "$upscope") {
            std::string end;
            in >> end;
            if (!scope.empty()) scope.pop_back();
        } else if (token == "$var") {
            std::string kind, width, code, name, rest, full;
            in >> kind >> width >> code >> name;
            for (const std::string& s : scope) full += s + ".";
            full += name;
            while (in >> rest && rest != "$end") full += rest;  // "[7:0]"
            v->code_of[full] = code;
            v->width_of[full] = std::stoi(width);
        } else if (token == "$enddefinitions") {
            in >> token;
            v->ok = !v->code_of.empty();
            return;
        } else if (token[0] == '$') {
            while (in >> token && token != "$end") {
            }
        }
    }
}

}  // namespace

const std::vector<vcd_change>& vcd_file::of(const std::string& name) const {
    static const std::vector<vcd_change> none;
    const auto c = code_of.find(name);
    if (c == code_of.end()) return none;
    const auto h = changes.find(c->second);
    return h == changes.end() ? none : h->second;
}

std::vector<vcd_change> vcd_file::history(const std::string& name) const {
    std::vector<vcd_change> h;
    const auto c = code_of.find(name);
    if (c == code_of.end()) return h;
    const auto f = first.find(c->second);
    if (f != first.end()) h.push_back({first_fs, f->second});
    const std::vector<vcd_change>& rest = of(name);
    h.insert(h.end(), rest.begin(), rest.end());
    return h;
}

vcd_file read_vcd(const std::string& path) {
    vcd_file v;
    std::ifstream in(path);
    read_header(in, &v);
    std::string token;
    int64_t now = -1;
    while (in >> token) {
        if (token[0] == '#') {
            now = std::stoll(token.substr(1));
            if (now < v.last_fs) v.times_increase = false;
            if (v.first_fs < 0) v.first_fs = now;
            v.last_fs = now;
            continue;
        }
        if (token[0] == '$') continue;  // $dumpvars / $end: the first time's values anyway
        std::string code, value;
        if (token[0] == 'b' || token[0] == 'B') {
            in >> code;
            value = without_leading_zeros(token.substr(1));
        } else {
            code = token.substr(1);
            value = token.substr(0, 1);
        }
        ++v.value_count;
        if (now == v.first_fs)
            v.first[code] = value;
        else
            v.changes[code].push_back({now, value});
    }
    return v;
}

}  // namespace testsupport
