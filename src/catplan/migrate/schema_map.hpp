#pragma once
// Schema maps (the paper's ontology maps) F : D' -> D, from a target schema D' to queries over a
// source schema D. Data flows the other way: Δ_F takes D-states to D'-states (migration.hpp).
//
//   target generator        image
//   object c'               a conjunctive query Q_c' over D (query.hpp); a plain object c is the
//                           query with one variable over c (a delta entry)
//   hom f' : c' -> d'       a query morphism Q_d' -> Q_c': each variable of Q_d' goes to a term of
//                           Q_c' (a variable, or a path from one); found by homomorphism search
//                           with those bindings, and it must exist and be unique. Between plain
//                           queries, a path of source homs (a delta entry).
//   attribute type T'       a source attribute type, or a value kind alone ("Float64"), in which
//                           case every attribute into T' must be a constant
//   attribute a' : c' -> T' a term of Q_c' ending in a value (path then attribute, or a value
//                           variable), or a constant (`x -> 0.0`)
//
// A map is built with the map_* functions (by the language elaborator or by code) and then
// finish()ed, which validates it and returns every problem as data, naming the target generator
// and the range of its entry so that the elaborator can locate it. A hom of an object whose query
// is @empty needs no image (its domain has no elements).
//
//   SchemaMap f(kitchen, blocks);
//   f.map_ob(object, Query::representable(blocks, block));
//   f.map_hom_path(in_receptacle_l, {on_l});
//   auto problems = f.finish();

#include "catplan/base/diagnostic.hpp"
#include "catplan/base/result.hpp"
#include "catplan/hom/morphism.hpp"
#include "catplan/migrate/query.hpp"
#include "catplan/schema/schema.hpp"

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace catplan::migrate {

using hom::ACSetMorphism;
using schema::Generator;
using schema::GeneratorKind;
using schema::ValueKind;

enum class MapProblemKind {
    Unmapped,             // a target generator has no image
    MappedTwice,          // a target generator was given two images (the later one is kept)
    BadQuery,             // a query (or a term of an image) is ill-formed
    WrongEnds,            // a hom's image does not start/end where its ends map
    NotUnique,            // a hom's image determines more than one query morphism
    EquationNotPreserved, // two equal target paths map to different source paths / morphisms
    WrongValueKind,       // an attribute (or constant) of the wrong attribute type or value kind
    NotConstant,          // an attribute into a kind-only type that is not a constant
    FreeValueVariable,    // a value variable that no attribute reaches (infinitely many tuples)
    IdentityImage,        // (warning) a hom sent to an identity path
};

/// One problem of a schema map, as data, with the target generator it concerns.
struct MapProblem {
    Severity severity = Severity::Error;
    MapProblemKind kind = MapProblemKind::Unmapped;
    Generator target{GeneratorKind::Ob, 0};
    SourceRange range; // the entry of the map, when it has one
    std::string message;
};

/// The compiled image of an attribute: a constant, a value of the domain's query shape, or a
/// path from a part of the shape ending in an attribute (evaluated in the state being migrated).
struct AttrImage {
    enum class Kind : std::uint8_t { None, Constant, Value, Path };
    Kind kind = Kind::None;
    Value constant;          // Constant
    AttrTypeId type;         // Value: the query variable's type
    Value value;             // Value: a variable (or constant) of the query shape
    ObId start_ob;           // Path: the part it starts at
    Part start = kNoPart;    // Path
    std::vector<HomId> homs; // Path
    AttrId attr;             // Path
};

/// The compiled image of a hom f' : c' -> d'.
struct HomImage {
    /// Between plain queries: the source path from c's variable (a delta entry).
    std::optional<std::vector<HomId>> path;
    /// Otherwise: the query morphism Q_d' -> Q_c'.
    std::optional<ACSetMorphism> morphism;
};

class SchemaMap {
public:
    /// A map with nothing mapped yet, from `target` (D') to queries over `source` (D).
    SchemaMap(SchemaPtr target, SchemaPtr source);

    const SchemaPtr& target() const { return target_; }

    const SchemaPtr& source() const { return source_; }

    // ---- building ----------------------------------------------------------------------------
    /// Sends a target object to a query over the source.
    void map_ob(ObId target, Query query, SourceRange range = {});
    /// Sends a target object to a source object (the query with one variable named after it).
    void map_ob(ObId target, ObId source, SourceRange range = {});
    /// Sends a target hom to a query morphism: node_images[i] is the term of the domain's query
    /// that node i of the codomain's query goes to.
    void map_hom(HomId target, std::vector<Term> node_images, SourceRange range = {});
    /// Sends a target hom to a path of source homs from the domain's (single) variable.
    void map_hom_path(HomId target, std::vector<HomId> path, SourceRange range = {});
    /// Sends a target attribute type to a source attribute type.
    void map_attr_type(AttrTypeId target, AttrTypeId source, SourceRange range = {});
    /// Sends a target attribute type to a value kind alone (its attributes must be constants).
    void map_attr_type(AttrTypeId target, ValueKind kind, SourceRange range = {});
    /// Sends a target attribute to a term of the domain's query that ends in a value.
    void map_attr(AttrId target, Term term, SourceRange range = {});
    /// Sends a target attribute to a constant function.
    void map_attr_constant(AttrId target, Value value, SourceRange range = {});

    /// Validates and compiles the map; returns every problem (errors and warnings). The map can
    /// be used for migration when no problem is an error.
    std::vector<MapProblem> finish();

    /// Whether finish() found no errors.
    bool ok() const { return finished_ && ok_; }

    // ---- reading -----------------------------------------------------------------------------
    /// The query of a target object.
    const Query& query(ObId target) const { return *obs_[target.index()].query; }

    /// The compiled image of a target hom (after finish()).
    const HomImage& hom_image(HomId target) const { return homs_[target.index()].image; }

    /// The source attribute type of a target attribute type, or nullopt for a kind-only one.
    std::optional<AttrTypeId> attr_type_image(AttrTypeId target) const {
        return attr_types_[target.index()].type;
    }

    /// The value kind of a target attribute type's image.
    ValueKind attr_type_kind(AttrTypeId target) const;

    /// The compiled image of a target attribute (after finish()).
    const AttrImage& attr_image(AttrId target) const { return attrs_[target.index()].image; }

    /// Every query is plain and every hom a path: a functor D' -> D, migrated column by column.
    bool is_delta() const;

    /// The source object of a plain query.
    ObId plain_ob(ObId target) const { return query(target).nodes()[0].ob; }

private:
    struct ObEntry {
        std::optional<Query> query;
        SourceRange range;
        bool set = false;
    };

    struct HomEntry {
        std::optional<std::vector<Term>> terms;
        std::optional<std::vector<HomId>> path;
        SourceRange range;
        bool set = false;
        HomImage image;
    };

    struct AttrTypeEntry {
        std::optional<AttrTypeId> type;
        ValueKind kind = ValueKind::Unknown;
        SourceRange range;
        bool set = false;
    };

    struct AttrEntry {
        std::optional<Term> term;
        std::optional<Value> constant;
        SourceRange range;
        bool set = false;
        AttrImage image;
    };

    void compile_hom(HomId f, std::vector<MapProblem>& out);
    bool compile_hom_path(HomId f, std::vector<MapProblem>& out);
    void unmapped_problems(std::vector<MapProblem>& out);
    void free_value_problems(std::vector<MapProblem>& out) const;
    void compile_attr(AttrId a, std::vector<MapProblem>& out);
    void check_equations(std::vector<MapProblem>& out);

    SchemaPtr target_, source_;
    std::vector<ObEntry> obs_;
    std::vector<HomEntry> homs_;
    std::vector<AttrTypeEntry> attr_types_;
    std::vector<AttrEntry> attrs_;
    std::vector<MapProblem> build_problems_;
    bool finished_ = false;
    bool ok_ = false;
};

/// The map whose migration is Δ_second ∘ Δ_first: for first : D' -> D and second : D'' -> D',
/// a map D'' -> D. Supported when first or second is a delta map (both maps must be finished and
/// ok); two conjunctive maps give a Failure saying so.
Result<SchemaMap> compose(const SchemaMap& first, const SchemaMap& second);

} // namespace catplan::migrate
