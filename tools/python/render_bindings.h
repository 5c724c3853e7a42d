// plantfield.render and plantfield.Renderer (docs/PYTHON.md "Rendering"):
// frames of a scene rendered headless into NumPy arrays.
#pragma once

#include <pybind11/pybind11.h>

void bindRender(pybind11::module_& m);
