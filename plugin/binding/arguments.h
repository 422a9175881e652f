// Reading a plugin function's named arguments, and the solver options among them.
#pragma once

#include "ff++.hpp"

#include "service/options.h"

#include <string>
#include <vector>

namespace ffeti::binding {

using NamedParameters = std::vector<basicAC_F0::name_and_type>;

/// A plugin function with named arguments: `nargs[i]` is the expression given for
/// `names[i]` (nullptr: not given).
class WithNamedArguments : public E_F0mps {
 protected:
  WithNamedArguments(const basicAC_F0& args, NamedParameters& names) : nargs(names.size()) {
    args.SetNameParam(static_cast<int>(names.size()), names.data(), nargs.data());
  }
  std::vector<Expression> nargs;
};

template <class T>
T* optional_pointer(Expression e, Stack stack) {
  return e ? GetAny<T*>((*e)(stack)) : nullptr;
}
double optional_real(Expression e, Stack stack, double fallback);
std::string optional_string(Expression e, Stack stack, const std::string& fallback);

/// A function's named parameters: its own (`extras`), then the registry's options of `scope`
/// (service/options.h), whose values the script gives as FreeFEM reals, integers or strings.
NamedParameters named_parameters(NamedParameters extras, OptionScope scope);

/// The options of `scope` the script gave: `options_nargs` points at the first of them
/// (named_parameters' order). Each is checked as it is read, before any narrowing.
GivenOptions given_options(OptionScope scope, const Expression* options_nargs, Stack stack);

}  // namespace ffeti::binding
