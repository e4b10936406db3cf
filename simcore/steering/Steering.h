#pragma once
// The steering-behaviour library in one include: agent and geometry structs, every
// behaviour, the combiners and the vehicle model. Declares nothing of its own.

#include "simcore/steering/Containment.h"
#include "simcore/steering/FlockingBehaviours.h"
#include "simcore/steering/FlowFollowing.h"
#include "simcore/steering/LeaderFollowing.h"
#include "simcore/steering/Neighbour.h"
#include "simcore/steering/ObstacleAvoidance.h"
#include "simcore/steering/PathFollowing.h"
#include "simcore/steering/PursuitBehaviours.h"
#include "simcore/steering/SteeringAgent.h"
#include "simcore/steering/SteeringCombination.h"
#include "simcore/steering/SteeringGeometry.h"
#include "simcore/steering/SteeringRequestList.h"
#include "simcore/steering/TargetBehaviours.h"
#include "simcore/steering/UnalignedCollisionAvoidance.h"
#include "simcore/steering/VehicleModel.h"
#include "simcore/steering/WallAvoidance.h"
#include "simcore/steering/Wander.h"
