// One contact discretization (a kind: node to node, node to segment, a rigid obstacle, node
// to face, mortar, ...) behind one interface: its capability row, the input it owns, which input
// selects it and its rows, each with its geometry (contact_row_geometry.h). build_constraints
// runs the registry in order; the capability table, fetiSetup's arguments and ffeti-solve's
// keys of the kinds that own their input are built from it. Adding a kind is a unit here and
// one line in contact_discretizations() (docs/architecture.md, "A contact kind").
#pragma once

#include "constraints/capabilities.h"
#include "constraints/constraint_records.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace ffeti {

struct Row;

/// What the contact rows are built from: the records of all ranks (`records` sorted by
/// (subdomain, dof)), the scalar parameters of `contact` (its per-subdomain lists are not
/// read) and the snapping length.
struct ContactRecords {
  const std::vector<DofRecord>& records;
  const std::vector<SegmentRecord>& segments;
  const std::vector<FaceRecord>& faces;
  const ContactInput& contact;
  double snap;
};

/// One field of a kind's own input: `size` numbers (kDimension: as many as the problem has
/// dimensions, a point or a vector), or a flag (true or false; 1 or 0 in a script's array).
struct InputField {
  static constexpr int kDimension = 0;
  const char* key;  ///< its key in the problem file's object; its name in messages
  int size;
  bool flag = false;
  bool nonzero = false;  ///< a direction: all zero is refused (in a problem file, naming the key)
};

/// The input a kind owns, read alike by both front ends: fetiSetup's real array `argument`
/// holds the fields' entries in order (the optional ones, last, may be left out), a problem
/// file's contact entry the object `file_key` with one key per field.
struct KindInput {
  const char* argument;  ///< fetiSetup's named argument: "obstacleBall"
  const char* file_key;  ///< the key of a problem file's contact entry (nullptr: none)
  std::vector<InputField> fields;
  size_t required;       ///< the first `required` fields must be given
  /// The array's layout, for messages: "[cx, cy, cz, radius]".
  const char* layout;
  /// A problem file may give, in a plane problem and instead of the first two fields (a
  /// point and a normal), this key naming a straight physical curve: the line through it,
  /// its normal towards the slave nodes (the plane obstacle's "curve"; nullptr: none).
  const char* line_key = nullptr;
};

/// What ffeti-solve reads from the mesh region a list kind's problem-file key names, as the
/// entries of the kind's list: each node's dofs (one entry per dof), or the region's
/// segments (triangles in a solid), each as its corners' dofs ordered so that its normal
/// points out of the body holding it (the lists' convention: contactSegments, contactFaces).
enum class MeshEntries : std::uint8_t { node_dofs, segments, triangles };

/// A scalar argument a list kind owns beside its list (node to node's gap, node to face's
/// contactNormal): fetiSetup's named argument and a problem file's key in a contact entry of
/// the kind, a real number or a word (one of `words`; its value is the word's position).
struct ListOption {
  const char* argument;            ///< fetiSetup's: "contactNormal"
  const char* file_key;            ///< a problem file's: "contact_normal"
  std::vector<const char*> words;  ///< empty: a real number
  /// Where the key means something, for a problem file's message "<key>: applies to <applies> only".
  const char* applies;
};

/// The position of `word` among the option's words, -1 if none.
int word_position(const ListOption& option, const std::string& word);
/// Why `word` is refused: "must be \"master\", \"slave\" or \"average\", got \"<word>\"".
std::string word_refusal(const ListOption& option, const std::string& word);

/// The per-subdomain list a kind owns: fetiSetup's int[int][int] argument, one array of dofs
/// per subdomain, `dofs` of them per entry (contactSlave, which several kinds share, stays
/// the front end's); and where a problem file gives it, the key of a contact entry naming a
/// physical group, read by ffeti-solve for the problems of `file_components` components.
struct ListInput {
  const char* argument;  ///< fetiSetup's named argument: "contactSegments"
  size_t dofs;           ///< per entry: a master segment's 4, a face's 9
  const char* layout;    ///< for messages: "4 dofs per segment (a_x, a_y, b_x, b_y)"
  const char* file_key = nullptr;  ///< the problem file's key: "master" (nullptr: none)
  int file_components = 0;         ///< the problem's "components" for which the key makes this kind
  MeshEntries file_entries = MeshEntries::node_dofs;  ///< what the key's group gives
  std::vector<ListOption> options = {};               ///< its scalar arguments, read by read_option
};

class ContactDiscretization {
 public:
  virtual ~ContactDiscretization() = default;
  /// Its position in the registry (the kinds that other code names return their name).
  virtual ContactKind kind() const;
  /// Its row of the capability table (`kind` is set by the registry).
  virtual KindCapabilities capabilities() const = 0;
  /// The input it owns (nullptr: it reads ContactInput's shared lists).
  virtual const KindInput* input() const { return nullptr; }
  /// The per-subdomain list it owns (nullptr: none).
  virtual const ListInput* list_input() const { return nullptr; }
  /// Stores list_input()'s lists, one per subdomain of this rank (`ids`: their numbers in
  /// messages; the dofs already checked against each subdomain's size), into its own input in
  /// `contact` (a struct of its unit, ContactInput::input_of): InputError "<argument>[<id>]:
  /// needs <layout>" for a list that is not whole entries.
  virtual void read_list(const std::vector<std::vector<int>>& /*lists*/, const std::vector<int>& /*ids*/,
                         ContactInput& /*contact*/) const {}
  /// Whether ffeti-solve reads the slave group of a contact entry into its list too, as it
  /// reads the master group (node to face with contactNormal slave or average: the slave
  /// surface's faces give the rows' normal, and get no rows).
  virtual bool lists_slave_group(const ContactInput& /*contact*/) const { return false; }
  /// Stores the value of list_input()->options[option] (a word's position) into its own input.
  virtual void read_option(size_t /*option*/, double /*value*/, ContactInput& /*contact*/) const {}
  /// Checks the entries given to input()'s argument in a problem of `dimension` (2 or 3) and
  /// stores them into `contact`: InputError "<argument>: ..." on bad entries. The default
  /// keeps them as ContactInput::kind_parameters[kind()], checked by check_parameters.
  virtual void read_input(const std::vector<double>& values, int dimension, ContactInput& contact) const;
  /// InputError "<argument>: ..." unless `values`, as many as input()'s fields take, are a
  /// valid input in `dimension` (a kind that keeps its input in kind_parameters).
  virtual void check_parameters(const std::vector<double>& /*values*/, int /*dimension*/) const {}
  /// The number of entries against input()'s fields, then check_parameters: read_input and
  /// validate_input (a caller that fills kind_parameters itself) ask it.
  void check_input(const std::vector<double>& values, int dimension) const;
  /// Its input's checks against the subdomains (`ids`: their numbers in messages) in a
  /// problem of `dimension`: its list's dofs within each subdomain and what its entries must
  /// be (a face's corners and orientation), its rows' dimensions. validate_input asks every
  /// unit, for callers other than fetiSetup too; InputError naming its argument.
  virtual void check_against(const std::vector<SubdomainInput>& /*subdomains*/, const std::vector<size_t>& /*ids*/,
                             const ContactInput& /*contact*/, int /*dimension*/) const {}
  /// Whether `contact` gives its list (an entry on this rank): a kind that owns its input
  /// (kind_parameters) takes contactSlave's nodes and refuses it (check_kind_inputs).
  virtual bool list_given(const ContactInput& /*contact*/) const { return false; }
  /// Its rule against the other kinds' input (issue 54): InputError naming the arguments
  /// where `contact` gives its lists together with input that would choose another kind
  /// for the same slaves. validate_input asks every unit; the default refuses nothing.
  virtual void check_combination(const ContactInput& /*contact*/) const {}
  /// Its list's part of the records of a rank's subdomains (constraint_records.h), from the
  /// input it owns in `local_contact` (the rank's own): the dofs of local subdomain k it makes
  /// slave or master nodes (one flag per dof), its master segments, its faces (master, or a
  /// mortar's slave faces), as records of the local subdomains (`global_ids`: their global
  /// indices; add_segment_records, add_face_records).
  virtual void flag_dofs(const ContactInput& /*local_contact*/, size_t /*k*/, std::vector<char>& /*slave*/,
                         std::vector<char>& /*master*/) const {}
  virtual void add_segments(const std::vector<SubdomainInput>& /*local*/, const std::vector<int>& /*global_ids*/,
                            const ContactInput& /*local_contact*/, std::vector<SegmentRecord>& /*segments*/) const {}
  virtual void add_faces(const std::vector<SubdomainInput>& /*local*/, const std::vector<int>& /*global_ids*/,
                         const ContactInput& /*local_contact*/, std::vector<FaceRecord>& /*faces*/) const {}
  /// Whether the input asks for this kind (on all ranks' records alike).
  virtual bool selected(const ContactRecords& in) const = 0;
  /// Appends one contact row per slave node (or none where no master is within reach).
  virtual void add_rows(const ContactRecords& in, std::vector<Row>& rows) const = 0;
  /// A kind that searches masters for its slaves: the argument naming them and what a
  /// master is ("segment", "face"), for the error when no slave found one. nullptr: rows
  /// come without a search.
  virtual const char* searched_argument() const { return nullptr; }
  virtual const char* master_word() const { return nullptr; }
};

/// Whether any subdomain's list of a per-subdomain list has an entry.
template <class Lists>
bool any_entry(const Lists& lists) {
  return std::any_of(lists.begin(), lists.end(), [](const auto& list) { return !list.empty(); });
}

/// Every kind, in the order its rows follow one another in B.
const std::vector<std::unique_ptr<const ContactDiscretization>>& contact_discretizations();

/// Whether `contact` gives the list of `kind` (its unit's list_given): a kind's rule against
/// another's input asks it so, without reading that kind's own input.
bool list_given(ContactKind kind, const ContactInput& contact);

/// The kinds that own their input (input() != nullptr), in the registry's order.
std::vector<const ContactDiscretization*> kinds_with_input();

/// The kinds that own a per-subdomain list (list_input() != nullptr), in the registry's order.
std::vector<const ContactDiscretization*> kinds_with_lists();

/// The list kinds' scalar arguments (ListInput::options) in the registry's order, each with
/// its kind and its position among the kind's (read_option's `option`).
struct KindOption {
  const ContactDiscretization* kind;
  size_t index;
  const ListOption* option;
};
std::vector<KindOption> list_options();

/// The kind whose list a problem file's contact entry gives by its key (ListInput::file_key)
/// in a problem of `components` field components (nullptr: none).
const ContactDiscretization* file_list_kind(int components);

/// `lists` cut into entries of N dofs (N = spec.dofs): InputError "<argument>[<id>]: needs
/// <layout>" for a list that is not whole entries.
void check_whole_entries(const ListInput& spec, const std::vector<std::vector<int>>& lists, const std::vector<int>& ids);
template <size_t N>
std::vector<std::vector<std::array<int, N>>> list_entries(const ListInput& spec, const std::vector<std::vector<int>>& lists,
                                                          const std::vector<int>& ids) {
  check_whole_entries(spec, lists, ids);
  std::vector<std::vector<std::array<int, N>>> result(lists.size());
  for (size_t k = 0; k < lists.size(); ++k)
    for (size_t i = 0; i < lists[k].size(); i += N) {
      std::array<int, N> entry{};
      std::copy_n(lists[k].begin() + static_cast<std::ptrdiff_t>(i), N, entry.begin());
      result[k].push_back(entry);
    }
  return result;
}

/// The entries of a kind's array argument from its fields as read one by one (a problem
/// file's object): `given[i]` empty where field i was left out. InputError naming the field
/// (prefixed by `where`) for a missing required field or one of the wrong size.
std::vector<double> input_values(const KindInput& input, const std::vector<std::vector<double>>& given, int dimension,
                                 const std::string& where);

}  // namespace ffeti
