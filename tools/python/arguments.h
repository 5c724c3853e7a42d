// The checks every binding of the module makes on its arguments before any
// work, so that a bad argument raises a Python exception instead of reaching
// C++ that assumes it valid (a None grammar was a null pointer): TypeError
// naming the argument for a wrong type, ValueError for a value out of range.
// And the output rule (lsystem/common/output_file.h) for the module's writers:
// the session's inputs are every file the module read since it was imported,
// so `write_png(render(scene), scene)` is refused like `plantfield --capture
// SCENE` is.
#pragma once

#include <cstddef>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

#include <pybind11/pybind11.h>

#include "lsystem/common/file_reader.h"

namespace pyargs {

// "NoneType", "float", "str": the Python type of `value`, for messages.
std::string typeName(pybind11::handle value);

// `value` as the bound class T, or TypeError "NAME must be EXPECTED, not TYPE".
template <class T>
std::shared_ptr<T> objectArgument(pybind11::handle value, const char* name, const char* expected) {
    if (!pybind11::isinstance<T>(value))
        throw pybind11::type_error(std::string(name) + " must be " + expected + ", not " + typeName(value));
    return value.cast<std::shared_ptr<T>>();
}

// Arguments pybind11 cannot convert: its own TypeError lists the whole
// signature and leaves the reader to find the argument at fault. So each
// binding is a wrapper taking (*args, **kwargs) that first tries every
// argument against its parameter's type, raising TypeError naming the first
// that does not convert, what it must be and what it was ("derive(): steps
// must be None or an integer -2147483648 to 2147483647, not str"), then calls
// the typed function (a pybind11 function of its own, whose signature and
// docstring the wrapper shows).

// A parameter as its py::arg declares it.
struct Parameter {
    std::string name;
    bool convert = true;   // false for py::arg(...).noconvert()
    bool required = false; // a py::arg without a default
};

// The parameters among a binding's extras (its py::arg and py::arg_v; the
// docstring is not a parameter).
inline void collectParameter(std::vector<Parameter>& out, const pybind11::arg_v& a) {
    out.push_back({a.name, !a.flag_noconvert, false});
}
inline void collectParameter(std::vector<Parameter>& out, const pybind11::arg& a) {
    out.push_back({a.name, !a.flag_noconvert, true});
}
template <class Extra>
void collectParameter(std::vector<Parameter>&, const Extra&) {}

template <class... Extra>
std::vector<Parameter> parametersOf(const Extra&... extra) {
    std::vector<Parameter> parameters;
    (collectParameter(parameters, extra), ...);
    return parameters;
}

template <class T>
struct IsOptional : std::false_type {};
template <class T>
struct IsOptional<std::optional<T>> : std::true_type {};

// What a value of C++ type T must be, in Python's words.
template <class T>
std::string expectedType() {
    using U = std::remove_cvref_t<T>;
    if constexpr (std::is_same_v<U, bool>) {
        return "True or False";
    } else if constexpr (std::is_integral_v<U>) {
        return "an integer " + std::to_string(std::numeric_limits<U>::min()) + " to " +
               std::to_string(std::numeric_limits<U>::max());
    } else if constexpr (std::is_floating_point_v<U>) {
        return "a number";
    } else if constexpr (IsOptional<U>::value) {
        return "None or " + expectedType<typename U::value_type>();
    } else {
        return pybind11::detail::make_caster<U>::name.text; // "os.PathLike", "str", "Tuple[int, int]"
    }
}

// "str", or an int's value ("-1"): what the argument was.
std::string givenValue(pybind11::handle value);

// The parameter types of a function, lambda or member function (less the object).
template <class F>
struct ParameterTypes : ParameterTypes<decltype(&F::operator())> {};
template <class R, class... A>
struct ParameterTypes<R (*)(A...)> {
    using Types = std::tuple<A...>;
};
template <class R, class C, class... A>
struct ParameterTypes<R (C::*)(A...)> {
    using Types = std::tuple<A...>;
};
template <class R, class C, class... A>
struct ParameterTypes<R (C::*)(A...) const> {
    using Types = std::tuple<A...>;
};

// The arguments of a call, by parameter: those given and their values.
struct BoundArguments {
    std::vector<pybind11::handle> values;
    std::vector<bool> given;
};

// Binds positional arguments (after `skip`, the object of a method) and
// keywords to the parameters, raising Python's own TypeErrors for too many,
// unknown, repeated or missing ones.
BoundArguments bindArguments(const std::string& function, const std::vector<Parameter>& parameters,
                             const pybind11::args& args, const pybind11::kwargs& kwargs, size_t skip);

template <class Types, size_t... I>
void checkArgumentTypes(const std::string& function, const std::vector<Parameter>& parameters,
                        const BoundArguments& bound, std::index_sequence<I...>) {
    const auto check = [&]<class T>(size_t i, std::type_identity<T>) {
        if (!bound.given[i]) return;
        pybind11::detail::make_caster<std::remove_cvref_t<T>> caster;
        if (!caster.load(bound.values[i], parameters[i].convert))
            throw pybind11::type_error(function + "(): " + parameters[i].name + " must be " + expectedType<T>() +
                                       ", not " + givenValue(bound.values[i]));
    };
    (check(I, std::type_identity<std::tuple_element_t<I, Types>>{}), ...);
}

// The wrapper of `typed`, a pybind11 function made from F with these extras.
template <class F, class... Extra>
auto checkedCall(std::string function, size_t skip, pybind11::object typed, const Extra&... extra) {
    using Types = typename ParameterTypes<F>::Types;
    static_assert(std::tuple_size_v<Types> == (0 + ... + std::is_base_of_v<pybind11::arg, Extra>),
                  "every parameter needs its py::arg");
    return [function = std::move(function), skip, typed = std::move(typed),
            parameters = parametersOf(extra...)](pybind11::args args, pybind11::kwargs kwargs) -> pybind11::object {
        checkArgumentTypes<Types>(function, parameters, bindArguments(function, parameters, args, kwargs, skip),
                                  std::make_index_sequence<std::tuple_size_v<Types>>{});
        return typed(*args, **kwargs);
    };
}

// Replaces a bound function's docstring with the typed function's: its
// signature and documentation, where the wrapper's would read (*args, **kwargs).
void setDocstring(pybind11::handle function, pybind11::handle typed);

// m.def(name, f, extra...), its arguments named when they do not convert.
template <class F, class... Extra>
void defChecked(pybind11::module_& m, const char* name, F f, const Extra&... extra) {
    pybind11::cpp_function typed(f, pybind11::name(name), extra...);
    m.def(name, checkedCall<F>(name, 0, typed, extra...));
    setDocstring(m.attr(name), typed);
}

// The same for a method of a bound class (the object comes first).
template <class Class, class Holder, class F, class... Extra>
void defChecked(pybind11::class_<Class, Holder>& c, const char* name, F f, const Extra&... extra) {
    pybind11::cpp_function typed(pybind11::method_adaptor<Class>(f), pybind11::name(name), pybind11::is_method(c),
                                 extra...);
    c.def(name, checkedCall<F>(name, 1, typed, extra...));
    setDocstring(c.attr(name), typed);
}

// The same for a constructor from a factory returning the class's holder
// (std::shared_ptr, so the typed function's result can be handed on).
template <class Class, class F, class... Extra>
void defCheckedInit(pybind11::class_<Class, std::shared_ptr<Class>>& c, const char* className, F factory,
                    const Extra&... extra) {
    pybind11::cpp_function typed(factory, pybind11::name(className), extra...);
    c.def(pybind11::init(
        [call = checkedCall<F>(className, 0, typed, extra...)](pybind11::args args, pybind11::kwargs kwargs) {
            return call(args, kwargs).template cast<std::shared_ptr<Class>>();
        }));
    setDocstring(c.attr("__init__"), typed);
}

// steps: none, or 0 to the longest derivation a plant file may ask for.
void checkSteps(const std::optional<int>& steps);

// defines: values that are finite numbers.
void checkDefines(const std::unordered_map<std::string, double>& defines);

// While alive, records the files the thread reads (a lsys::ReadFileLog);
// closing adds them to the session's inputs, which no writer replaces.
class SessionReads {
public:
    SessionReads() = default;
    SessionReads(const SessionReads&) = delete;
    SessionReads& operator=(const SessionReads&) = delete;
    ~SessionReads();

private:
    lsys::ReadFileLog log_;
};

// ValueError "NAME: cannot write 'PATH': REASON" when `path` is not a file
// a writer may replace (a folder, a device, a file the session read).
void checkOutput(const std::filesystem::path& path, const char* name);

} // namespace pyargs
