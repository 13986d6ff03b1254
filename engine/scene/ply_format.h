#pragma once
// Private to the PLY loader (ply_loader.cpp): the format's header (Turk 1994) and a reader of the
// values after it, ascii or binary, that refuses to read past the file's end.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/error.h"

namespace mvpl::scene::ply {

enum class Format { ascii, little_endian, big_endian };

enum class Type { i8, u8, i16, u16, i32, u32, f32, f64 };

struct Property {
    std::string name;
    Type type = Type::f32;
    bool is_list = false;
    Type count_type = Type::u8;
};

struct Element {
    std::string name;
    uint64_t count = 0;
    std::vector<Property> properties;
};

// Bytes of one binary value of type t.
size_t type_size(Type t);

struct Header {
    Format format = Format::ascii;
    std::vector<Element> elements;
    size_t data_offset = 0;
};

// The header of the file `path` whose contents are `data`; throws InputError on a defect.
Header parse_header(const std::string& path, const std::string& data);

// Reads the values after the header, ascii or binary, one at a time.
class Reader {
public:
    Reader(const std::string& path, const std::string& data, size_t offset, Format format)
        : m_path(path), m_data(data), m_pos(offset), m_format(format) {}

    double read(Type type, const char* what) {
        return m_format == Format::ascii ? read_ascii(what) : read_binary(type, what);
    }
    size_t remaining() const { return m_data.size() - m_pos; }

private:
    [[noreturn]] void fail(const std::string& what) const { throw InputError(m_path, what); }
    double read_ascii(const char* what);
    double read_binary(Type type, const char* what);

    const std::string& m_path;
    const std::string& m_data;
    size_t m_pos;
    Format m_format;
};

}  // namespace mvpl::scene::ply
