#include "binding/arguments.h"

namespace ffeti::binding {

double optional_real(Expression e, Stack stack, double fallback) {
  return e ? GetAny<double>((*e)(stack)) : fallback;
}

std::string optional_string(Expression e, Stack stack, const std::string& fallback) {
  return e ? *GetAny<std::string*>((*e)(stack)) : fallback;
}

NamedParameters named_parameters(NamedParameters extras, OptionScope scope) {
  for (const Option& o : options())
    if (o.scope == scope)
      extras.push_back({o.name, o.kind == OptionKind::word      ? &typeid(std::string*)
                                : o.kind == OptionKind::integer ? &typeid(long)
                                                                : &typeid(double)});
  return extras;
}

GivenOptions given_options(OptionScope scope, const Expression* options_nargs, Stack stack) {
  GivenOptions given;
  size_t k = 0;
  for (const Option& o : options()) {
    if (o.scope != scope) continue;
    const Expression e = options_nargs[k++];
    if (!e) continue;
    // By the option itself, not its name: a name looks up the set-up and solve scopes only,
    // which refused the sensitivity functions' own activeTol.
    if (o.kind == OptionKind::word) given.set(o, *GetAny<std::string*>((*e)(stack)));
    else if (o.kind == OptionKind::integer) given.set(o, GetAny<long>((*e)(stack)));
    else given.set(o, GetAny<double>((*e)(stack)));
  }
  return given;
}

}  // namespace ffeti::binding
