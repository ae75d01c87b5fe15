// The tier table of the fixture tree.
#pragma once
