/// @file lang/definition_order.h
/// @brief The order in which lowering takes the `let` and `solid` definitions: each after
/// every definition it uses, found by an iterative walk (Tarjan's strongly connected
/// components), so that lowering never recurses through names and a chain of names costs no
/// stack whatever order it is written in. Also each definition's level (kMaxNameDepth).
#pragma once

#include "lang/ast.h"

#include <map>
#include <string>
#include <vector>

namespace kerf {

struct OrderedDefinition {
    const Statement* def = nullptr;
    /// 1 for a definition that uses no other; else 1 + the largest level among those it uses.
    int level = 1;
    /// The definitions it uses directly (each once).
    std::vector<const Statement*> uses;
    /// Where it uses a definition at level kMaxNameDepth, when its own level is one more: the
    /// place to report that the chain is too deep (deeper definitions fail quietly).
    SourcePos tooDeepAt;
    bool firstTooDeep = false;
};

/// The definitions named in `lets` and `solids` (name → its first definition), each after
/// every definition it uses. Definitions on a cycle of names, or that use one, are left out:
/// lowering meets them in statement order and reports the cycle as it finds it.
std::vector<OrderedDefinition> definitionOrder(
    const std::map<std::string, const Statement*>& lets,
    const std::map<std::string, const Statement*>& solids,
    const DiagnosticSink& sink);  ///< finds the lines

}  // namespace kerf
