// The shading model (common/shading_model.h, shared with the CPU reference).
#include "shading_model.h"
