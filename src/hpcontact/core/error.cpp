// Anchor translation unit for the core module.
#include "hpcontact/core/error.hpp"
