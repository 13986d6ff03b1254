#include "engine/scene/gltf_accessor.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <stdexcept>

namespace mvpl::scene::gltf {
namespace {

static_assert(std::endian::native == std::endian::little, "glTF buffers are little-endian");

// An accessor without a buffer view costs no file bytes, so its count alone must be bounded;
// any other count is bounded by the bytes it must find in its buffer view.
constexpr size_t kMaxZeroElements = size_t(1) << 24;

const char* type_name(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return "SCALAR";
        case TINYGLTF_TYPE_VEC2:
            return "VEC2";
        case TINYGLTF_TYPE_VEC3:
            return "VEC3";
        case TINYGLTF_TYPE_VEC4:
            return "VEC4";
        case TINYGLTF_TYPE_MAT2:
            return "MAT2";
        case TINYGLTF_TYPE_MAT3:
            return "MAT3";
        case TINYGLTF_TYPE_MAT4:
            return "MAT4";
        default:
            return "an unknown type";
    }
}

int component_count(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return 1;
        case TINYGLTF_TYPE_VEC2:
            return 2;
        case TINYGLTF_TYPE_VEC3:
            return 3;
        case TINYGLTF_TYPE_VEC4:
            return 4;
        default:
            return 0;
    }
}

std::string component_name(int component_type) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return "byte";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return "unsigned byte";
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return "short";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return "unsigned short";
        case TINYGLTF_COMPONENT_TYPE_INT:
            return "int";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return "unsigned int";
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return "float";
        case TINYGLTF_COMPONENT_TYPE_DOUBLE:
            return "double";
        default:
            return "unknown (" + std::to_string(component_type) + ")";
    }
}

size_t component_size(int component_type) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return 2;
        case TINYGLTF_COMPONENT_TYPE_INT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return 4;
        case TINYGLTF_COMPONENT_TYPE_DOUBLE:
            return 8;
        default:
            return 0;
    }
}

template <typename T>
T load(const unsigned char* p) {
    T value;
    std::memcpy(&value, p, sizeof(T));
    return value;
}

float component_as_float(const unsigned char* p, int component_type, bool normalized) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return load<float>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
            const float v = float(load<uint8_t>(p));
            return normalized ? v / 255.0f : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            const float v = float(load<uint16_t>(p));
            return normalized ? v / 65535.0f : v;
        }
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            const float v = float(load<int8_t>(p));
            return normalized ? std::max(v / 127.0f, -1.0f) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            const float v = float(load<int16_t>(p));
            return normalized ? std::max(v / 32767.0f, -1.0f) : v;
        }
        default:
            return 0.0f;  // excluded by the AccessorNeeds check
    }
}

uint32_t component_as_uint(const unsigned char* p, int component_type) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return load<uint8_t>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return load<uint16_t>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return load<uint32_t>(p);
        default:
            return 0;  // excluded by the AccessorNeeds check
    }
}

bool is_index_type(int component_type) {
    return component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
           component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
           component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

}  // namespace

AccessorView::AccessorView(const Document& doc, int index, AccessorNeeds needs)
    : m_doc(doc), m_index(index) {
    const auto& accessors = doc.model.accessors;
    if (index < 0 || size_t(index) >= accessors.size()) {
        doc.fail(needs.usage + " refers to accessor " + std::to_string(index) +
                 ", but the file has " + std::to_string(accessors.size()) + " accessors");
    }
    m_label = "accessor " + std::to_string(index) + " (" + needs.usage + ")";
    m_usage = needs.usage;
    const tinygltf::Accessor& accessor = accessors[size_t(index)];

    if (accessor.type != needs.type) {
        doc.fail(m_label + " must be " + type_name(needs.type) + ", not " +
                 type_name(accessor.type));
    }
    const bool allowed = std::find(needs.component_types.begin(), needs.component_types.end(),
                                   accessor.componentType) != needs.component_types.end();
    if (!allowed) {
        std::string wanted;
        for (int type : needs.component_types) {
            wanted += (wanted.empty() ? "" : " or ") + component_name(type);
        }
        doc.fail(m_label + " has " + component_name(accessor.componentType) +
                 " components; it needs " + wanted);
    }
    if (needs.integers_normalized && accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT &&
        !accessor.normalized) {
        doc.fail(m_label + " has integer components that are not normalized");
    }
    m_component_type = accessor.componentType;
    m_components = component_count(accessor.type);
    m_element_size = component_size(m_component_type) * size_t(m_components);
    m_normalized = accessor.normalized;
    m_count = accessor.count;

    if (accessor.bufferView != -1) {
        locate_data(accessor);
    } else if (m_count > kMaxZeroElements) {
        doc.fail(m_label + " has no buffer view and " + std::to_string(m_count) +
                 " elements, more than " + std::to_string(kMaxZeroElements));
    }
    if (accessor.sparse.isSparse) read_sparse(accessor);
}

void AccessorView::locate_data(const tinygltf::Accessor& accessor) {
    size_t stride = m_element_size;
    const auto& views = m_doc.model.bufferViews;
    if (size_t(accessor.bufferView) < views.size()) {
        const size_t view_stride = views[size_t(accessor.bufferView)].byteStride;
        if (view_stride != 0 && view_stride < m_element_size) {
            m_doc.fail(m_label + " has " + std::to_string(m_element_size) +
                       "-byte elements but buffer view " + std::to_string(accessor.bufferView) +
                       " has a byteStride of " + std::to_string(view_stride));
        }
        if (view_stride != 0) stride = view_stride;
    }
    m_stride = stride;
    m_data = view_bytes(accessor.bufferView, accessor.byteOffset, m_count, m_element_size, stride,
                        m_label);
}

void AccessorView::read_sparse(const tinygltf::Accessor& accessor) {
    const auto& sparse = accessor.sparse;
    if (sparse.count < 1 || size_t(sparse.count) > m_count) {
        m_doc.fail(m_label + " has " + std::to_string(sparse.count) +
                   " sparse elements; it must have between 1 and " + std::to_string(m_count));
    }
    if (!is_index_type(sparse.indices.componentType)) {
        m_doc.fail(m_label + " has sparse indices of " +
                   component_name(sparse.indices.componentType) +
                   " type; they must be unsigned byte, short or int");
    }
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0) {
        m_doc.fail(m_label + " has a negative sparse byteOffset");
    }
    m_sparse.count = size_t(sparse.count);
    m_sparse.index_component_type = sparse.indices.componentType;
    const size_t index_size = component_size(sparse.indices.componentType);
    m_sparse.indices =
        view_bytes(sparse.indices.bufferView, size_t(sparse.indices.byteOffset), m_sparse.count,
                   index_size, index_size, m_label + " sparse indices");
    m_sparse.values =
        view_bytes(sparse.values.bufferView, size_t(sparse.values.byteOffset), m_sparse.count,
                   m_element_size, m_element_size, m_label + " sparse values");
}

const unsigned char* AccessorView::view_bytes(int view_index, size_t offset, size_t count,
                                              size_t element_size, size_t stride,
                                              const std::string& what) const {
    const auto& views = m_doc.model.bufferViews;
    const auto& buffers = m_doc.model.buffers;
    if (view_index < 0 || size_t(view_index) >= views.size()) {
        m_doc.fail(what + " refers to buffer view " + std::to_string(view_index) +
                   ", but the file has " + std::to_string(views.size()) + " buffer views");
    }
    const tinygltf::BufferView& view = views[size_t(view_index)];
    const std::string view_name = "buffer view " + std::to_string(view_index);
    if (view.buffer < 0 || size_t(view.buffer) >= buffers.size()) {
        m_doc.fail(view_name + " refers to buffer " + std::to_string(view.buffer) +
                   ", but the file has " + std::to_string(buffers.size()) + " buffers");
    }
    const std::vector<unsigned char>& data = buffers[size_t(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset) {
        m_doc.fail(view_name + " (offset " + std::to_string(view.byteOffset) + ", length " +
                   std::to_string(view.byteLength) + ") extends past the end of buffer " +
                   std::to_string(view.buffer) + " (" + std::to_string(data.size()) + " bytes)");
    }
    const size_t length = view.byteLength;
    // offset + stride·(count − 1) + element ≤ length, arranged so that nothing can overflow.
    const bool fits = count == 0 ? offset <= length
                                 : element_size <= length && offset <= length - element_size &&
                                       (count - 1) <= (length - element_size - offset) / stride;
    if (!fits) {
        m_doc.fail(what + " reads past the end of " + view_name + ": " + std::to_string(count) +
                   " elements of " + std::to_string(element_size) + " bytes (stride " +
                   std::to_string(stride) + ") at offset " + std::to_string(offset) +
                   " do not fit in its " + std::to_string(length) + " bytes");
    }
    return data.data() + view.byteOffset + (count == 0 ? 0 : offset);
}

template <typename Visit>
void AccessorView::for_each_element(Visit&& visit) const {
    static const unsigned char kZeros[64] = {};
    for (size_t i = 0; i < m_count; ++i)
        visit(i, m_data ? m_data + i * m_stride : kZeros);
    const size_t index_size = component_size(m_sparse.index_component_type);
    for (size_t k = 0; k < m_sparse.count; ++k) {
        const uint32_t i =
            component_as_uint(m_sparse.indices + k * index_size, m_sparse.index_component_type);
        if (i >= m_count) {
            m_doc.fail(m_label + " has sparse index " + std::to_string(i) + " past its " +
                       std::to_string(m_count) + " elements");
        }
        visit(size_t(i), m_sparse.values + k * m_element_size);
    }
}

template <int N>
std::vector<glm::vec<N, float>> AccessorView::read_floats() const {
    if (N != m_components) throw std::logic_error(m_label + " read with the wrong width");
    std::vector<glm::vec<N, float>> out(m_count);
    const size_t size = component_size(m_component_type);
    for_each_element([&](size_t i, const unsigned char* p) {
        for (int c = 0; c < N; ++c) {
            out[i][c] = component_as_float(p + size_t(c) * size, m_component_type, m_normalized);
        }
    });
    return out;
}

std::vector<Vec2> AccessorView::read_vec2() const {
    return read_floats<2>();
}
std::vector<Vec3> AccessorView::read_vec3() const {
    return read_floats<3>();
}
std::vector<Vec4> AccessorView::read_vec4() const {
    return read_floats<4>();
}

std::vector<uint32_t> AccessorView::read_uints() const {
    if (m_components != 1) throw std::logic_error(m_label + " read as scalars");
    std::vector<uint32_t> out(m_count);
    for_each_element(
        [&](size_t i, const unsigned char* p) { out[i] = component_as_uint(p, m_component_type); });
    return out;
}

}  // namespace mvpl::scene::gltf
