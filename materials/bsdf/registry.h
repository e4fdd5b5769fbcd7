// The material registry now lives in materials/registry/; this header includes all of it until
// every file includes the piece it uses.
#pragma once

#include "materials/registry/material_file.h"
#include "materials/registry/material_model.h"
#include "materials/registry/model_list.h"
#include "materials/registry/parameter_spec.h"
#include "materials/registry/spec_validation.h"
