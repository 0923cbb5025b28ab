// The extension module ellvor._ellvor and its error mapping: ellvor::InputError
// becomes ellvor.InputError (a ValueError) with the location and the site
// pair as attributes, every other C++ exception ellvor.Error (a
// RuntimeError); Python's own exceptions (KeyboardInterrupt, an exception of
// a progress callback, TypeError, MemoryError) pass through unchanged.
#include "decision/predicate_registry.hpp"
#include "python/src/bindings.hpp"

#include "util/error.hpp"

#include <exception>
#include <new>

namespace ellvor::python {
namespace {

py::object error_class(const char* name) { return py::module_::import("ellvor._errors").attr(name); }

void raise_input_error(const InputError& e) {
    py::object cls = error_class("InputError");
    py::dict fields;
    fields["reason"] = e.reason();
    if (e.has_location()) {
        fields["filename"] = e.file();
        fields["lineno"] = e.line();
        fields["column"] = e.column();
    }
    if (e.sites()) fields["sites"] = py::make_tuple(e.sites()->first, e.sites()->second);
    if (const auto* crossing = dynamic_cast<const IntersectingSites*>(&e)) fields["why"] = crossing->why();
    py::object exc = cls(e.what(), **fields);
    PyErr_SetObject(cls.ptr(), exc.ptr());
}

}  // namespace

void register_errors(py::module_&) {
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const InputError& e) {
            raise_input_error(e);
        } catch (const py::builtin_exception&) {
            throw;  // pybind11's TypeError, ValueError, ...
        } catch (const py::error_already_set&) {
            throw;
        } catch (const std::bad_alloc&) {
            throw;  // MemoryError
        } catch (const std::exception& e) {
            PyErr_SetString(error_class("Error").ptr(), e.what());
        }
    });
}

}  // namespace ellvor::python

PYBIND11_MODULE(_ellvor, m) {
    m.doc() = "The compiled half of ellvor; import ellvor instead.";
    ellvor::python::register_errors(m);
    ellvor::python::bind_sites(m);
    ellvor::python::bind_diagram(m);
    ellvor::python::bind_cells(m);
    ellvor::python::bind_predicates(m);
    // The registries of decision/: the names of --stats, the JSON and Diagram.stats.
    pybind11::list predicates, stages;
    for (const ellvor::PredicateInfo& p : ellvor::kPredicates) predicates.append(p.name);
    for (ellvor::Stage s : ellvor::kStages) stages.append(ellvor::stage_name(s));
    m.attr("PREDICATES") = pybind11::tuple(predicates);
    m.attr("STAGES") = pybind11::tuple(stages);
}
