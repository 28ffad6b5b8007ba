// The HAL interfaces have virtual destructors, so every driver's vtable holds
// a "deleting destructor" that references operator delete. Nothing is ever
// allocated (operator new is not defined: a use fails to link), so these can
// never run; they trap instead of pulling in libstdc++'s heap.
#include <cstddef>

extern "C" void lumavel_fault_handler();

void operator delete(void*) noexcept { lumavel_fault_handler(); }
void operator delete(void*, std::size_t) noexcept { lumavel_fault_handler(); }
