// The generalist model compiled into the program (resources/models/generalist.fcdqn, made by
// floorcover-train-generalist on generated floors only): solver dqn uses it whenever no model
// file is given, and training a plan starts from it unless told to start from scratch.
#pragma once

#include "learning/dqn/DqnModelFile.h"

#include <memory>
#include <string>

namespace fc {

// How the generalist is named in messages and in the Training dock.
inline const std::string kGeneralistModelName = "the built-in generalist model";

// Parsed once (thread-safe) and shared. Throws InputError naming the model when the
// embedded bytes are not a generalist model (a build that shipped a wrong file).
std::shared_ptr<const DqnModel> generalistModel();

} // namespace fc
