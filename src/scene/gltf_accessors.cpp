// glTF 2.0 accessor decoding: gathers an accessor's elements into a tightly packed byte array
// (bufferView stride and offsets, sparse substitution), then converts the components.
#include "scene/gltf_accessors.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <bit>
#include <cstring>

#include "util/error.h"

namespace ontile::gltf {
namespace {

// glTF stores all binary data little-endian (spec 3.6.2.1); components are copied as bytes.
static_assert(std::endian::native == std::endian::little, "glTF decoding assumes little-endian");

// Upper bound on an accessor's element count, so a corrupt count without a bufferView (which
// reads as zeros) cannot ask for terabytes.
constexpr uint64_t kMaxAccessorElements = uint64_t{1} << 32;

[[noreturn]] void fail(const std::string& file_label, int accessor_index,
                       const std::string& problem) {
  throw Error(file_label + ": accessor " + std::to_string(accessor_index) + " " + problem);
}

int component_size_bytes(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;  // INT and DOUBLE are not valid accessor component types in glTF 2.0
  }
}

// Checks that bufferView `view_index` exists and lies inside its buffer; returns it.
const tinygltf::BufferView& checked_view(const tinygltf::Model& model, int view_index,
                                         const std::string& file_label, int accessor_index,
                                         const char* role) {
  if (view_index < 0 || static_cast<size_t>(view_index) >= model.bufferViews.size()) {
    fail(file_label, accessor_index,
         std::string(role) + " refers to bufferView " + std::to_string(view_index) +
             ", which does not exist (the file has " + std::to_string(model.bufferViews.size()) +
             ")");
  }
  const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(view_index)];
  if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size()) {
    fail(file_label, accessor_index,
         std::string(role) + ": bufferView " + std::to_string(view_index) + " refers to buffer " +
             std::to_string(view.buffer) + ", which does not exist");
  }
  const size_t buffer_bytes = model.buffers[static_cast<size_t>(view.buffer)].data.size();
  if (view.byteOffset > buffer_bytes || view.byteLength > buffer_bytes - view.byteOffset) {
    fail(file_label, accessor_index,
         std::string(role) + ": bufferView " + std::to_string(view_index) + " (byteOffset " +
             std::to_string(view.byteOffset) + ", byteLength " + std::to_string(view.byteLength) +
             ") exceeds buffer " + std::to_string(view.buffer) + " (" +
             std::to_string(buffer_bytes) + " bytes)");
  }
  return view;
}

const uint8_t* view_bytes(const tinygltf::Model& model, const tinygltf::BufferView& view) {
  return model.buffers[static_cast<size_t>(view.buffer)].data.data() + view.byteOffset;
}

// The accessor's elements, tightly packed, after sparse substitution (spec 3.6.2.3: an
// accessor without bufferView starts as zeros).
struct PackedElements {
  std::vector<uint8_t> bytes;
  size_t count = 0;
  int components = 0;
  int component_type = 0;
  size_t element_bytes = 0;
};

void apply_sparse(const tinygltf::Model& model, const tinygltf::Accessor& accessor,
                  const std::string& file_label, int accessor_index, PackedElements& packed) {
  const auto& sparse = accessor.sparse;
  if (sparse.count < 1 || static_cast<size_t>(sparse.count) > packed.count) {
    fail(file_label, accessor_index,
         "sparse count " + std::to_string(sparse.count) + " is outside 1.." +
             std::to_string(packed.count));
  }
  const size_t substitutions = static_cast<size_t>(sparse.count);
  const int index_size = component_size_bytes(sparse.indices.componentType);
  if (sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
    fail(file_label, accessor_index,
         "sparse indices have invalid componentType " +
             std::to_string(sparse.indices.componentType));
  }
  if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0) {
    fail(file_label, accessor_index, "sparse byteOffset is negative");
  }
  const auto& index_view =
      checked_view(model, sparse.indices.bufferView, file_label, accessor_index, "sparse indices");
  const auto& value_view =
      checked_view(model, sparse.values.bufferView, file_label, accessor_index, "sparse values");
  // Sparse indices and values are tightly packed (spec 3.6.2.3).
  const size_t index_begin = static_cast<size_t>(sparse.indices.byteOffset);
  const size_t value_begin = static_cast<size_t>(sparse.values.byteOffset);
  if (index_begin > index_view.byteLength ||
      substitutions * static_cast<size_t>(index_size) > index_view.byteLength - index_begin) {
    fail(file_label, accessor_index,
         "sparse indices (" + std::to_string(substitutions) + " x " + std::to_string(index_size) +
             " bytes at offset " + std::to_string(index_begin) + ") exceed bufferView " +
             std::to_string(sparse.indices.bufferView) + " (" +
             std::to_string(index_view.byteLength) + " bytes)");
  }
  if (value_begin > value_view.byteLength ||
      substitutions * packed.element_bytes > value_view.byteLength - value_begin) {
    fail(file_label, accessor_index,
         "sparse values (" + std::to_string(substitutions) + " x " +
             std::to_string(packed.element_bytes) + " bytes at offset " +
             std::to_string(value_begin) + ") exceed bufferView " +
             std::to_string(sparse.values.bufferView) + " (" +
             std::to_string(value_view.byteLength) + " bytes)");
  }
  const uint8_t* index_data = view_bytes(model, index_view) + index_begin;
  const uint8_t* value_data = view_bytes(model, value_view) + value_begin;
  for (size_t i = 0; i < substitutions; ++i) {
    uint32_t target = 0;
    if (index_size == 1) {
      target = index_data[i];
    } else if (index_size == 2) {
      uint16_t v;
      std::memcpy(&v, index_data + 2 * i, 2);
      target = v;
    } else {
      std::memcpy(&target, index_data + 4 * i, 4);
    }
    if (target >= packed.count) {
      fail(file_label, accessor_index,
           "sparse index " + std::to_string(target) + " out of range (count " +
               std::to_string(packed.count) + ")");
    }
    std::memcpy(packed.bytes.data() + target * packed.element_bytes,
                value_data + i * packed.element_bytes, packed.element_bytes);
  }
}

PackedElements pack_elements(const tinygltf::Model& model, int accessor_index,
                             const std::string& file_label) {
  if (accessor_index < 0 || static_cast<size_t>(accessor_index) >= model.accessors.size()) {
    fail(file_label, accessor_index,
         "does not exist (the file has " + std::to_string(model.accessors.size()) + " accessors)");
  }
  const tinygltf::Accessor& accessor = model.accessors[static_cast<size_t>(accessor_index)];
  PackedElements packed;
  packed.count = accessor.count;
  packed.component_type = accessor.componentType;
  packed.components = component_count_of_type(accessor.type);
  const int component_bytes = component_size_bytes(accessor.componentType);
  if (component_bytes == 0) {
    fail(file_label, accessor_index,
         "has unsupported componentType " + std::to_string(accessor.componentType));
  }
  if (packed.components == 0) {
    fail(file_label, accessor_index, "has a matrix type, which no vertex attribute uses");
  }
  if (packed.count > kMaxAccessorElements) {
    fail(file_label, accessor_index, "has implausible count " + std::to_string(packed.count));
  }
  packed.element_bytes =
      static_cast<size_t>(component_bytes) * static_cast<size_t>(packed.components);
  // Every bound is checked before the elements are allocated: a count of 2^29 over a 36-byte
  // bufferView must fail here, not after gigabytes of zeros.
  const uint8_t* source = nullptr;
  size_t stride = 0;
  if (accessor.bufferView >= 0 && packed.count > 0) {
    const auto& view =
        checked_view(model, accessor.bufferView, file_label, accessor_index, "bufferView");
    // byteStride 0 means tightly packed (spec 3.6.2.4); a stride must hold a whole element.
    stride = view.byteStride == 0 ? packed.element_bytes : view.byteStride;
    if (stride < packed.element_bytes || stride % static_cast<size_t>(component_bytes) != 0) {
      fail(file_label, accessor_index,
           "byteStride " + std::to_string(stride) + " does not fit elements of " +
               std::to_string(packed.element_bytes) + " bytes");
    }
    // Bytes read: [byteOffset, byteOffset + stride * (count - 1) + element size).
    const size_t begin = accessor.byteOffset;
    const bool fits = begin <= view.byteLength &&
                      (packed.count - 1) <= (view.byteLength - begin) / stride &&
                      stride * (packed.count - 1) + packed.element_bytes <= view.byteLength - begin;
    if (!fits) {
      fail(file_label, accessor_index,
           "(byteOffset " + std::to_string(begin) + ", count " + std::to_string(packed.count) +
               ", stride " + std::to_string(stride) + ") reads past the end of bufferView " +
               std::to_string(accessor.bufferView) + " (" + std::to_string(view.byteLength) +
               " bytes)");
    }
    source = view_bytes(model, view) + begin;
  }
  packed.bytes.assign(packed.count * packed.element_bytes, 0);
  if (source) {
    for (size_t i = 0; i < packed.count; ++i) {
      std::memcpy(packed.bytes.data() + i * packed.element_bytes, source + i * stride,
                  packed.element_bytes);
    }
  }
  if (accessor.sparse.isSparse) apply_sparse(model, accessor, file_label, accessor_index, packed);
  return packed;
}

template <typename T>
T load_component(const uint8_t* bytes) {
  T value;
  std::memcpy(&value, bytes, sizeof(T));
  return value;
}

}  // namespace

int component_count_of_type(int accessor_type) {
  switch (accessor_type) {
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

std::vector<float> read_accessor_floats(const tinygltf::Model& model, int accessor_index,
                                        const std::string& file_label) {
  const PackedElements packed = pack_elements(model, accessor_index, file_label);
  const bool normalized = model.accessors[static_cast<size_t>(accessor_index)].normalized;
  const size_t value_count = packed.count * static_cast<size_t>(packed.components);
  std::vector<float> values(value_count);
  const uint8_t* bytes = packed.bytes.data();
  // Spec 3.11 (normalized integers): signed types use max(c / (2^(n-1) - 1), -1), unsigned
  // types c / (2^n - 1). FLOAT and UNSIGNED_INT must not be normalized (spec 3.6.2.2).
  switch (packed.component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      for (size_t i = 0; i < value_count; ++i) {
        const float c = static_cast<float>(load_component<int8_t>(bytes + i));
        values[i] = normalized ? std::max(c / 127.0f, -1.0f) : c;
      }
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      for (size_t i = 0; i < value_count; ++i) {
        const float c = static_cast<float>(bytes[i]);
        values[i] = normalized ? c / 255.0f : c;
      }
      break;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      for (size_t i = 0; i < value_count; ++i) {
        const float c = static_cast<float>(load_component<int16_t>(bytes + 2 * i));
        values[i] = normalized ? std::max(c / 32767.0f, -1.0f) : c;
      }
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      for (size_t i = 0; i < value_count; ++i) {
        const float c = static_cast<float>(load_component<uint16_t>(bytes + 2 * i));
        values[i] = normalized ? c / 65535.0f : c;
      }
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      if (normalized) {
        fail(file_label, accessor_index,
             "is normalized, which componentType " + std::to_string(packed.component_type) +
                 " does not allow");
      }
      for (size_t i = 0; i < value_count; ++i) {
        values[i] = packed.component_type == TINYGLTF_COMPONENT_TYPE_FLOAT
                        ? load_component<float>(bytes + 4 * i)
                        : static_cast<float>(load_component<uint32_t>(bytes + 4 * i));
      }
      break;
  }
  return values;
}

std::vector<uint32_t> read_accessor_indices(const tinygltf::Model& model, int accessor_index,
                                            const std::string& file_label) {
  const PackedElements packed = pack_elements(model, accessor_index, file_label);
  const tinygltf::Accessor& accessor = model.accessors[static_cast<size_t>(accessor_index)];
  if (packed.components != 1 || accessor.normalized) {
    fail(file_label, accessor_index, "is used as indices but is not a plain SCALAR");
  }
  std::vector<uint32_t> indices(packed.count);
  const uint8_t* bytes = packed.bytes.data();
  switch (packed.component_type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      for (size_t i = 0; i < packed.count; ++i) indices[i] = bytes[i];
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      for (size_t i = 0; i < packed.count; ++i)
        indices[i] = load_component<uint16_t>(bytes + 2 * i);
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      for (size_t i = 0; i < packed.count; ++i)
        indices[i] = load_component<uint32_t>(bytes + 4 * i);
      break;
    default:
      fail(file_label, accessor_index,
           "is used as indices but has componentType " + std::to_string(packed.component_type) +
               " (indices must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT)");
  }
  return indices;
}

}  // namespace ontile::gltf
