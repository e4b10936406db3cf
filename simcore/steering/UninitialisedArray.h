#pragma once
// Stack room for up to N values of a plain type, left uninitialised: for the hot
// per-agent buffers of which only the first `count` entries are used, each written
// before it is read. (A std::array of a struct with member initialisers writes all N
// every time it is declared, which in the per-agent loop costs more than filling it.)

#include <cstddef>
#include <new>
#include <type_traits>

namespace throng::sim {

template <typename T, std::size_t N>
class UninitialisedArray {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                  "only plain data may live in uninitialised storage");

public:
    UninitialisedArray() {}  // leaves the bytes as they are, on purpose
    T* data() { return std::launder(reinterpret_cast<T*>(m_bytes)); }
    const T* data() const { return std::launder(reinterpret_cast<const T*>(m_bytes)); }
    T& operator[](std::size_t k) { return data()[k]; }
    const T& operator[](std::size_t k) const { return data()[k]; }
    static constexpr std::size_t capacity() { return N; }

private:
    alignas(T) std::byte m_bytes[N * sizeof(T)];
};

}  // namespace throng::sim
