#include "engine/scene/ply_format.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <sstream>
#include <utility>

namespace mvpl::scene::ply {

namespace {

std::optional<Type> parse_type(const std::string& name) {
    if (name == "char" || name == "int8") return Type::i8;
    if (name == "uchar" || name == "uint8") return Type::u8;
    if (name == "short" || name == "int16") return Type::i16;
    if (name == "ushort" || name == "uint16") return Type::u16;
    if (name == "int" || name == "int32") return Type::i32;
    if (name == "uint" || name == "uint32") return Type::u32;
    if (name == "float" || name == "float32") return Type::f32;
    if (name == "double" || name == "float64") return Type::f64;
    return std::nullopt;
}

template <typename T>
T load(const unsigned char* b) {
    T value;
    std::memcpy(&value, b, sizeof value);
    return value;
}

}  // namespace

size_t type_size(Type t) {
    switch (t) {
        case Type::i8:
        case Type::u8:
            return 1;
        case Type::i16:
        case Type::u16:
            return 2;
        case Type::i32:
        case Type::u32:
        case Type::f32:
            return 4;
        case Type::f64:
            return 8;
    }
    return 1;
}

Header parse_header(const std::string& path, const std::string& data) {
    auto fail = [&path](const std::string& what) -> void {
        throw InputError(path, "bad PLY header: " + what);
    };
    if (data.empty()) throw InputError(path, "file is empty");
    Header h;
    size_t pos = 0;
    bool have_format = false, ended = false;
    for (int line_number = 1; !ended; ++line_number) {
        const size_t eol = data.find('\n', pos);
        if (eol == std::string::npos) fail("no end_header line");
        std::string line = data.substr(pos, eol - pos);
        if (!line.empty() && line.back() == '\r') line.pop_back();
        pos = eol + 1;
        std::istringstream in(line);
        std::string word;
        in >> word;
        if (line_number == 1) {
            if (line != "ply") fail("the file does not start with 'ply'");
            continue;
        }
        const std::string where = " (line " + std::to_string(line_number) + ")";
        if (word == "format") {
            std::string name, version;
            in >> name >> version;
            if (name == "ascii")
                h.format = Format::ascii;
            else if (name == "binary_little_endian")
                h.format = Format::little_endian;
            else if (name == "binary_big_endian")
                h.format = Format::big_endian;
            else
                fail("unknown format '" + name + "'" + where);
            if (version != "1.0") fail("unsupported version '" + version + "'" + where);
            have_format = true;
        } else if (word == "element") {
            Element e;
            std::string count;
            in >> e.name >> count;
            char* stop = nullptr;
            const unsigned long long n = std::strtoull(count.c_str(), &stop, 10);
            if (e.name.empty() || count.empty() || *stop != '\0' || count[0] == '-')
                fail("bad element line '" + line + "'" + where);
            e.count = n;
            h.elements.push_back(e);
        } else if (word == "property") {
            if (h.elements.empty()) fail("property before any element" + where);
            Property p;
            std::string type;
            in >> type;
            if (type == "list") {
                std::string count_type, item_type;
                in >> count_type >> item_type >> p.name;
                const auto ct = parse_type(count_type), it = parse_type(item_type);
                if (!ct || !it || p.name.empty()) fail("bad list property '" + line + "'" + where);
                if (*ct == Type::f32 || *ct == Type::f64) fail("float list count" + where);
                p.is_list = true;
                p.count_type = *ct;
                p.type = *it;
            } else {
                in >> p.name;
                const auto t = parse_type(type);
                if (!t || p.name.empty()) fail("bad property '" + line + "'" + where);
                p.type = *t;
            }
            h.elements.back().properties.push_back(p);
        } else if (word == "end_header") {
            ended = true;
        } else if (word != "comment" && word != "obj_info" && !word.empty()) {
            fail("unknown keyword '" + word + "'" + where);
        }
    }
    if (!have_format) fail("no format line");
    h.data_offset = pos;
    return h;
}

double Reader::read_ascii(const char* what) {
    while (m_pos < m_data.size() && std::isspace(static_cast<unsigned char>(m_data[m_pos])))
        ++m_pos;
    if (m_pos == m_data.size()) fail(std::string("truncated ascii PLY: no value for ") + what);
    size_t end = m_pos;
    while (end < m_data.size() && !std::isspace(static_cast<unsigned char>(m_data[end])))
        ++end;
    const std::string token = m_data.substr(m_pos, std::min<size_t>(end - m_pos, 64));
    char* stop = nullptr;
    const double value = std::strtod(token.c_str(), &stop);
    if (end - m_pos > 64 || stop != token.c_str() + token.size())
        fail("bad number '" + token + "' for " + what + " in ascii PLY");
    m_pos = end;
    return value;
}

double Reader::read_binary(Type type, const char* what) {
    const size_t size = type_size(type);
    if (remaining() < size) fail(std::string("truncated binary PLY: data ends in ") + what);
    unsigned char b[8];
    std::memcpy(b, m_data.data() + m_pos, size);
    m_pos += size;
    const bool swap =
        (m_format == Format::big_endian) == (std::endian::native == std::endian::little);
    if (swap) {
        for (size_t i = 0; i < size / 2; ++i)
            std::swap(b[i], b[size - 1 - i]);
    }
    switch (type) {
        case Type::i8:
            return double(int8_t(b[0]));
        case Type::u8:
            return double(b[0]);
        case Type::i16:
            return double(load<int16_t>(b));
        case Type::u16:
            return double(load<uint16_t>(b));
        case Type::i32:
            return double(load<int32_t>(b));
        case Type::u32:
            return double(load<uint32_t>(b));
        case Type::f32:
            return double(load<float>(b));
        case Type::f64:
            return load<double>(b);
    }
    return 0.0;
}

}  // namespace mvpl::scene::ply
