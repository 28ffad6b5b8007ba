// Storage for an object built at run time (it needs references to other
// objects) and never destroyed: no atexit registration, no heap. Firmware
// singletons (the App, the drivers) live in one of these.
#pragma once
#include <new>

namespace lumavel::board {

template <class T>
class StaticObject {
 public:
  template <class... Args>
  T& emplace(Args&&... args) {
    return *::new (static_cast<void*>(storage_)) T(static_cast<Args&&>(args)...);
  }

 private:
  alignas(T) unsigned char storage_[sizeof(T)];
};

}  // namespace lumavel::board
