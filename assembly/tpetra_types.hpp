#pragma once
// The one Tpetra instantiation Grout uses (Debian's Trilinos 13.2: LO int, GO long long,
// SC double, Serial node). Every Tpetra type in Grout is spelled through these aliases.

#include <Tpetra_CrsGraph.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

namespace grout {

using LO = int;
using GO = long long;
using Node = Tpetra::Map<>::node_type;
using Map = Tpetra::Map<LO, GO, Node>;
static_assert(std::is_same_v<Tpetra::Map<>::global_ordinal_type, GO>,
              "grout: Tpetra must be instantiated with GO = long long");
using Graph = Tpetra::CrsGraph<LO, GO, Node>;
using Matrix = Tpetra::CrsMatrix<double, LO, GO, Node>;
using Vector = Tpetra::Vector<double, LO, GO, Node>;
using MultiVector = Tpetra::MultiVector<double, LO, GO, Node>;
using Operator = Tpetra::Operator<double, LO, GO, Node>;
using Import = Tpetra::Import<LO, GO, Node>;
using Export = Tpetra::Export<LO, GO, Node>;
using Comm = Teuchos::Comm<int>;

}  // namespace grout
