#pragma once
// The buffer family's techniques, one file each; bufferEntries() (buffer_family.cpp) lists them.
#include "oit/technique.hpp"

namespace strata {

TechniqueEntry kbufferEntry();  // oit/buffers/kbuffer.cpp
TechniqueEntry fabEntry();      // oit/buffers/fab.cpp
TechniqueEntry llEntry();       // oit/buffers/linked_lists.cpp
TechniqueEntry sbufferEntry();  // oit/buffers/sbuffer.cpp

}  // namespace strata
