#include "solver/solver.h"

#include "solver/bf_oracle.h"
#include "hierarchy/cluster.h"
#include "solver/link_transport.h"
#include "hierarchy/polygon_element.h"
#include "emitters/sky_patch_element.h"
#include "terrain/terrain_mesh.h"
#include "hierarchy/terrain_patch.h"
#include "visibility/visibility.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

// Refinement (paper section 3): links split while the BF oracle says they carry too much,
// and leaves split where shadows cross them or terrain meshes must stay restricted.
namespace terralux
{
bool HierarchicalRadiosity::mayGrow()
{
  // Links count too: at tight tolerances every pair of small elements wants a link, so
  // links can grow as the square of the elements while hardly any element is added.
  if (this->elementCount() < this->Options.maximumElements &&
    this->StoredLinks + this->PendingLinks < 4 * this->Options.maximumElements)
    return true;
  this->Stats.elementBudgetReached = true;
  return false;
}

std::size_t HierarchicalRadiosity::refine(std::vector<std::pair<HElement*, Link>>& pending, bool evaluated)
{
  std::size_t splits = 0;
  OracleSettings oracle = this->oracleSettings();
  std::vector<std::pair<HElement*, Link>> next;
  // New, not yet evaluated links from every child of `split` to / from `other`.
  auto addChildLinks = [&next](HElement* receiver, HElement* sender, bool splitReceiver) {
    for (HElement* child : (splitReceiver ? receiver : sender)->children())
    {
      Link sub;
      sub.sender = splitReceiver ? sender : child;
      next.emplace_back(splitReceiver ? child : receiver, sub);
    }
  };
  while (!pending.empty())
  {
    if (!evaluated)
    {
      tbb::parallel_for(std::size_t(0), pending.size(), [&](std::size_t k) {
        HElement* receiver = pending[k].first;
        HElement* sender = pending[k].second.sender;
        if (receiver != sender)
        {
          pending[k].second = evaluateLink(*receiver, *sender, *this->Rays, this->Options.visibilitySamples);
        }
      });
    }
    next.clear();
    for (auto& [receiver, link] : pending)
    {
      this->PendingLinks = pending.size() + next.size();
      HElement* sender = link.sender;
      if (receiver == sender)
      {
        // A cluster's self-link becomes links between all pairs of its members;
        // a planar surface does not light itself.
        if (receiver->isCluster())
        {
          for (HElement* member : receiver->children())
            addChildLinks(receiver, member, true);
        }
        else if (lightsItself(*receiver, oracle) && this->mayGrow() && !receiver->children().empty())
        {
          ++splits;
          for (HElement* part : receiver->children())
            addChildLinks(receiver, part, true);
        }
        continue;
      }
      if (!(link.kernel > 0.0 && link.visibility > 0.0) &&
        (clusterMayCarryMore(*receiver, link, oracle) || modelMissesExchange(*receiver, link, oracle)))
      {
        // A cluster's centre direction or its few samples saw nothing, but its members
        // may: split (the side decideRefinement picks) rather than drop.
        const Refinement decision = this->mayGrow() ? decideRefinement(*receiver, link, oracle) : Refinement::Keep;
        if (decision != Refinement::Keep)
        {
          ++splits;
          addChildLinks(receiver, sender, decision == Refinement::SplitReceiver);
        }
        continue;
      }
      if (!(link.kernel > 0.0))
      {
        // Carries nothing, now or later; but a rough terrain patch facing away from a
        // sky patch on average may hold slopes facing it: split while those could matter.
        Link rough = link;
        rough.kernel = link.kernelSpread;
        rough.visibility = 1.0;
        if (receiver->canSplit() && linkPower(*receiver, rough) > oracle.partialVisibilityFactor * oracle.powerThreshold &&
          this->mayGrow())
        {
          ++splits;
          addChildLinks(receiver, sender, true);
        }
        continue;
      }
      if (!(link.visibility > 0.0))
      {
        // No sample saw the sender; parts of a large receiver still may. Split the
        // receiver while the unoccluded transport would matter, else drop the link.
        Link unoccluded = link;
        unoccluded.visibility = 1.0;
        if (receiver->canSplit() &&
          linkPower(*receiver, unoccluded) > oracle.partialVisibilityFactor * oracle.powerThreshold && this->mayGrow())
        {
          ++splits;
          addChildLinks(receiver, sender, true);
        }
        continue;
      }
      const Refinement decision = decideRefinement(*receiver, link, oracle);
      if (decision != Refinement::Keep && !this->mayGrow())
      {
        receiver->Incoming.push_back(link); // over budget: the link stays as it is
        ++this->StoredLinks;
        continue;
      }
      switch (decision)
      {
        case Refinement::Keep:
          receiver->Incoming.push_back(link);
          ++this->StoredLinks;
          break;
        case Refinement::SplitReceiver:
          ++splits;
          addChildLinks(receiver, sender, true);
          break;
        case Refinement::SplitSender:
          ++splits;
          addChildLinks(receiver, sender, false);
          break;
      }
    }
    pending.swap(next);
    evaluated = false;
  }
  this->PendingLinks = 0;
  return splits;
}

std::size_t HierarchicalRadiosity::splitLeaves(const std::vector<PolygonElement*>& leaves)
{
  if (leaves.empty() || !this->mayGrow())
    return 0;
  // The leaves' links move to their children, evaluated and refined there.
  std::vector<std::pair<HElement*, Link>> pending;
  for (PolygonElement* polygon : leaves)
  {
    for (HElement* child : polygon->children())
      for (const Link& link : polygon->Incoming)
      {
        Link sub;
        sub.sender = link.sender;
        pending.emplace_back(child, sub);
      }
    this->StoredLinks -= polygon->Incoming.size();
    polygon->Incoming.clear();
  }
  if (!pending.empty())
  {
    this->refine(pending, false);
  }
  return leaves.size();
}

std::size_t HierarchicalRadiosity::splitShadowedLeaves()
{
  // A leaf lit through many partially visible links, none worth refining alone, still
  // averages a shadow over its area: split it when that light carries enough power.
  const double threshold = this->Options.errorTolerance * this->Stats.referencePowerW;
  std::vector<PolygonElement*> leaves;
  for (const auto& element : this->Store->all())
  {
    if (!element->isSurface())
      continue;
    auto* polygon = static_cast<PolygonElement*>(element.get());
    if (!polygon->hasChildren() && polygon->canSplit() && polygon->PartialIrradiance * polygon->area() > threshold)
      leaves.push_back(polygon);
  }
  return this->splitLeaves(leaves);
}

std::size_t HierarchicalRadiosity::restrictTerrainMeshes()
{
  // Restricted subdivision (paper section 4.2): no leaf has a neighbour more than one
  // level finer, i.e. more than one T-vertex on an edge, so shading varies gradually
  // from coarse to fine leaves. Splits cascade outward until none is needed.
  std::size_t splits = 0;
  for (;;)
  {
    std::vector<PolygonElement*> leaves;
    for (const TerrainPatch* root : this->TerrainRoots)
    {
      if (!root)
        continue;
      const TerrainLeafMesh mesh(*root);
      for (std::size_t k = 0; k < mesh.leaves().size(); ++k)
      {
        // Ids are positions in the store, which owns the (mutable) element.
        auto* leaf = static_cast<PolygonElement*>(this->Store->all()[mesh.leaves()[k]->id()].get());
        if (mesh.mostTVerticesOnAnEdge(k) > 1 && leaf->canSplit())
          leaves.push_back(leaf);
      }
    }
    const std::size_t split = leaves.empty() ? 0 : this->splitLeaves(leaves);
    if (split == 0)
      return splits; // done, or over the element budget
    splits += split;
  }
}

} // namespace terralux
