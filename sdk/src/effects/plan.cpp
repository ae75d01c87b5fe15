#include "sfx/status.hpp"
