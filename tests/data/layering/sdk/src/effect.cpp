// A file of the lowest layer that includes the tier table: the arrow check_layering.py must refuse.
#include "sfx/tier_rows.hpp"
