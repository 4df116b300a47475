// memcpy, memmove, memset and memcmp, which GCC may call even in freestanding code. Built with
// -fno-tree-loop-distribute-patterns so these loops are never turned back into calls to themselves.
// Word loops when both pointers are 4-byte aligned (v6-M faults on unaligned word access).
#include <stddef.h>
#include <stdint.h>

namespace {

using Word = uint32_t __attribute__((may_alias));  // callers' buffers have any type

bool both_aligned(const void* a, const void* b) {
    return ((reinterpret_cast<uintptr_t>(a) | reinterpret_cast<uintptr_t>(b)) & 3u) == 0;
}

}  // namespace

extern "C" {

void* memcpy(void* dst, const void* src, size_t n) {
    auto* d = static_cast<unsigned char*>(dst);
    const auto* s = static_cast<const unsigned char*>(src);
    if (both_aligned(d, s)) {
        for (; n >= 4; n -= 4, d += 4, s += 4)
            *reinterpret_cast<Word*>(d) = *reinterpret_cast<const Word*>(s);
    }
    for (; n != 0; --n) *d++ = *s++;
    return dst;
}

void* memmove(void* dst, const void* src, size_t n) {
    auto* d = static_cast<unsigned char*>(dst);
    const auto* s = static_cast<const unsigned char*>(src);
    if (reinterpret_cast<uintptr_t>(d) - reinterpret_cast<uintptr_t>(s) >= n) return memcpy(dst, src, n);
    while (n != 0) {  // dst overlaps the tail of src: copy backwards
        --n;
        d[n] = s[n];
    }
    return dst;
}

void* memset(void* dst, int value, size_t n) {
    auto* d = static_cast<unsigned char*>(dst);
    const auto byte = static_cast<unsigned char>(value);
    if (both_aligned(d, d)) {
        const uint32_t word = byte * 0x01010101u;
        Word* w = reinterpret_cast<Word*>(d);
        for (; n >= 32; n -= 32, w += 8) {  // eight words a turn: frame clears are large
            w[0] = word; w[1] = word; w[2] = word; w[3] = word;
            w[4] = word; w[5] = word; w[6] = word; w[7] = word;
        }
        for (; n >= 4; n -= 4) *w++ = word;
        d = reinterpret_cast<unsigned char*>(w);
    }
    for (; n != 0; --n) *d++ = byte;
    return dst;
}

int memcmp(const void* a, const void* b, size_t n) {
    const auto* p = static_cast<const unsigned char*>(a);
    const auto* q = static_cast<const unsigned char*>(b);
    for (; n != 0; --n, ++p, ++q) {
        if (*p != *q) return *p < *q ? -1 : 1;
    }
    return 0;
}

}  // extern "C"
