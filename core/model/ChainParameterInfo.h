#pragma once

#include "model/RobotModel.h"
#include "model/SerialChain.h"
#include "types/ChainSettings.h"

#include <QList>

namespace learnid {

/// Name, unit, description and group of each standard parameter of a chain, in ChainModel's
/// order: per link m_k, m·cx_k, m·cy_k, m·cz_k, Ixx_k .. Izz_k (the link's group), then per joint
/// the joint terms that are on (the joint's group); k as a subscript digit.
QList<ParameterInfo> standardParameterInfo(const SerialChain &chain, const JointTerms &terms);

} // namespace learnid
