// The contact discretizations build_constraints runs, in the order of their rows in B (that
// order is part of the numerics: keep it when adding a kind, append the new one), and what is
// built from them: each kind's position, the kinds that own their input and its reading.
#include "constraints/contact/ball.h"
#include "constraints/contact/contact_discretization.h"
#include "constraints/contact/cylinder.h"
#include "constraints/contact/mortar.h"
#include "constraints/contact/node_to_face.h"
#include "constraints/contact/node_to_node.h"
#include "constraints/contact/node_to_segment.h"
#include "constraints/contact/obstacle.h"

#include "base/errors.h"

#include <algorithm>

namespace ffeti {

const std::vector<std::unique_ptr<const ContactDiscretization>>& contact_discretizations() {
  static const auto units = [] {
    std::vector<std::unique_ptr<const ContactDiscretization>> list;
    list.push_back(std::make_unique<NodeToSegment>());
    list.push_back(std::make_unique<Obstacle>());
    list.push_back(std::make_unique<Ball>());
    list.push_back(std::make_unique<Mortar>());
    list.push_back(std::make_unique<NodeToFace>());
    list.push_back(std::make_unique<NodeToNode>());
    list.push_back(std::make_unique<Cylinder>());
    return list;
  }();
  return units;
}

ContactKind ContactDiscretization::kind() const {
  const auto& units = contact_discretizations();
  const auto at = std::find_if(units.begin(), units.end(), [this](const auto& unit) { return unit.get() == this; });
  return static_cast<ContactKind>(at - units.begin());
}

bool list_given(ContactKind kind, const ContactInput& contact) {
  return contact_discretizations().at(static_cast<size_t>(kind))->list_given(contact);
}

std::vector<const ContactDiscretization*> kinds_with_input() {
  std::vector<const ContactDiscretization*> kinds;
  for (const auto& unit : contact_discretizations())
    if (unit->input()) kinds.push_back(unit.get());
  return kinds;
}

std::vector<const ContactDiscretization*> kinds_with_lists() {
  std::vector<const ContactDiscretization*> kinds;
  for (const auto& unit : contact_discretizations())
    if (unit->list_input()) kinds.push_back(unit.get());
  return kinds;
}

std::vector<KindOption> list_options() {
  std::vector<KindOption> options;
  for (const ContactDiscretization* unit : kinds_with_lists())
    for (size_t i = 0; i < unit->list_input()->options.size(); ++i)
      options.push_back({unit, i, &unit->list_input()->options[i]});
  return options;
}

const ContactDiscretization* file_list_kind(int components) {
  for (const ContactDiscretization* unit : kinds_with_lists())
    if (unit->list_input()->file_key && unit->list_input()->file_components == components) return unit;
  return nullptr;
}

int word_position(const ListOption& option, const std::string& word) {
  for (size_t i = 0; i < option.words.size(); ++i)
    if (word == option.words[i]) return static_cast<int>(i);
  return -1;
}

std::string word_refusal(const ListOption& option, const std::string& word) {
  std::string choices;
  for (size_t i = 0; i < option.words.size(); ++i)
    choices += std::string(i == 0 ? "" : i + 1 == option.words.size() ? " or " : ", ") + "\"" + option.words[i] + "\"";
  return "must be " + choices + ", got \"" + word + "\"";
}

void check_whole_entries(const ListInput& spec, const std::vector<std::vector<int>>& lists, const std::vector<int>& ids) {
  for (size_t k = 0; k < lists.size(); ++k)
    if (lists[k].size() % spec.dofs != 0)
      throw InputError(std::string(spec.argument) + "[" + std::to_string(ids[k]) + "]: needs " + spec.layout);
}

namespace {

size_t field_size(const InputField& field, int dimension) {
  return field.flag ? 1 : field.size == InputField::kDimension ? static_cast<size_t>(dimension)
                                                              : static_cast<size_t>(field.size);
}

}  // namespace

std::vector<double> input_values(const KindInput& input, const std::vector<std::vector<double>>& given, int dimension,
                                 const std::string& where) {
  std::vector<double> values;
  for (size_t i = 0; i < input.fields.size(); ++i) {
    const InputField& field = input.fields[i];
    const std::vector<double>& entries = given[i];
    if (entries.empty()) {
      if (i < input.required) throw InputError(where + field.key + ": missing");
      continue;
    }
    const size_t size = field_size(field, dimension);
    if (entries.size() != size && field.size == InputField::kDimension)
      throw InputError(where + field.key + (dimension == 2 ? ": needs two numbers [x, y]"
                                                           : ": needs three numbers [x, y, z] (\"components\": 3)"));
    if (entries.size() != size)
      throw InputError(where + field.key + ": needs " + (size == 1 ? "one number" : std::to_string(size) + " numbers") +
                       ", got " + std::to_string(entries.size()));
    if (field.nonzero && std::all_of(entries.begin(), entries.end(), [](double v) { return v == 0; }))
      throw InputError(where + field.key + ": must not be zero");
    values.insert(values.end(), entries.begin(), entries.end());
  }
  return values;
}

void ContactDiscretization::check_input(const std::vector<double>& values, int dimension) const {
  const KindInput& spec = *input();
  size_t required = 0, all = 0;
  for (size_t i = 0; i < spec.fields.size(); ++i) {
    all += field_size(spec.fields[i], dimension);
    if (i + 1 == spec.required) required = all;
  }
  if (values.size() < required || values.size() > all)
    throw InputError(std::string(spec.argument) + ": needs " + spec.layout + ", got " + std::to_string(values.size()) +
                     " entries");
  check_parameters(values, dimension);
}

void ContactDiscretization::read_input(const std::vector<double>& values, int dimension, ContactInput& contact) const {
  const KindInput& spec = *input();
  check_input(values, dimension);
  if (contact.kind_parameters.count(kind()))
    throw InputError(std::string(spec.argument) + ": given twice (one " + capabilities().name + " per problem)");
  contact.kind_parameters[kind()] = values;
}

}  // namespace ffeti
