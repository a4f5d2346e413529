// The heap is a link error on this port (Pigweed's newlib_os_interface_stubs.cc idea):
// every way into newlib's allocator and every global operator new/delete is defined here
// to call a function that is declared but never defined. Unused, these definitions are
// dropped by --gc-sections and cost nothing; used, from lib/ or anywhere else, the link
// stops with "undefined reference to `aloft_heap_use_is_a_link_error_on_cortex_m'".
#include <cstddef>
#include <new>

extern "C" [[noreturn]] void aloft_heap_use_is_a_link_error_on_cortex_m();

extern "C" {
struct _reent;
void* malloc(std::size_t) { aloft_heap_use_is_a_link_error_on_cortex_m(); }
void free(void*) { aloft_heap_use_is_a_link_error_on_cortex_m(); }
void* calloc(std::size_t, std::size_t) { aloft_heap_use_is_a_link_error_on_cortex_m(); }
void* realloc(void*, std::size_t) { aloft_heap_use_is_a_link_error_on_cortex_m(); }
void* memalign(std::size_t, std::size_t) { aloft_heap_use_is_a_link_error_on_cortex_m(); }
int posix_memalign(void**, std::size_t, std::size_t) { aloft_heap_use_is_a_link_error_on_cortex_m(); }
void* aligned_alloc(std::size_t, std::size_t) { aloft_heap_use_is_a_link_error_on_cortex_m(); }
// newlib's reentrant entry points, which its own stdio and dtoa call directly.
void* _malloc_r(_reent*, std::size_t) { aloft_heap_use_is_a_link_error_on_cortex_m(); }
void _free_r(_reent*, void*) { aloft_heap_use_is_a_link_error_on_cortex_m(); }
void* _calloc_r(_reent*, std::size_t, std::size_t) { aloft_heap_use_is_a_link_error_on_cortex_m(); }
void* _realloc_r(_reent*, void*, std::size_t) { aloft_heap_use_is_a_link_error_on_cortex_m(); }
void* _memalign_r(_reent*, std::size_t, std::size_t) { aloft_heap_use_is_a_link_error_on_cortex_m(); }
// Where newlib's allocator gets its memory from.
void* _sbrk(std::ptrdiff_t) { aloft_heap_use_is_a_link_error_on_cortex_m(); }
void* _sbrk_r(_reent*, std::ptrdiff_t) { aloft_heap_use_is_a_link_error_on_cortex_m(); }
}

void* operator new(std::size_t) { aloft_heap_use_is_a_link_error_on_cortex_m(); }
void* operator new[](std::size_t) { aloft_heap_use_is_a_link_error_on_cortex_m(); }
void* operator new(std::size_t, const std::nothrow_t&) noexcept {
  aloft_heap_use_is_a_link_error_on_cortex_m();
}
void* operator new[](std::size_t, const std::nothrow_t&) noexcept {
  aloft_heap_use_is_a_link_error_on_cortex_m();
}
void* operator new(std::size_t, std::align_val_t) { aloft_heap_use_is_a_link_error_on_cortex_m(); }
void* operator new[](std::size_t, std::align_val_t) { aloft_heap_use_is_a_link_error_on_cortex_m(); }
void operator delete(void*) noexcept { aloft_heap_use_is_a_link_error_on_cortex_m(); }
void operator delete[](void*) noexcept { aloft_heap_use_is_a_link_error_on_cortex_m(); }
void operator delete(void*, std::size_t) noexcept { aloft_heap_use_is_a_link_error_on_cortex_m(); }
void operator delete[](void*, std::size_t) noexcept { aloft_heap_use_is_a_link_error_on_cortex_m(); }
void operator delete(void*, std::align_val_t) noexcept { aloft_heap_use_is_a_link_error_on_cortex_m(); }
void operator delete[](void*, std::align_val_t) noexcept { aloft_heap_use_is_a_link_error_on_cortex_m(); }
void operator delete(void*, std::size_t, std::align_val_t) noexcept {
  aloft_heap_use_is_a_link_error_on_cortex_m();
}
void operator delete[](void*, std::size_t, std::align_val_t) noexcept {
  aloft_heap_use_is_a_link_error_on_cortex_m();
}
