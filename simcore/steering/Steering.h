#pragma once
// The steering-behaviour library in one include: agent and geometry structs, every
// behaviour (through the behaviour list, BehaviourTable.h), the combiners and the vehicle
// model. Declares nothing of its own.

#include "simcore/scene/BehaviourTable.h"
#include "simcore/steering/Neighbour.h"
#include "simcore/steering/SteeringAgent.h"
#include "simcore/steering/SteeringCombination.h"
#include "simcore/steering/SteeringGeometry.h"
#include "simcore/steering/SteeringRequestList.h"
#include "simcore/steering/VehicleModel.h"
