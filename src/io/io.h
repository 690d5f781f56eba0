#pragma once
// Layer: io. Owns what crosses the program's boundary as results and inputs:
// case files (TOML) and their parameter schemas, JSON summaries, the HDF5
// results store. Sits after fem in the data flow; it reads results of every
// layer before it and computes nothing of its own.
#include "io/parameters.h"
