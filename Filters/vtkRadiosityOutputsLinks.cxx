// vtkRadiosityOutputs' third output: the links as lines from receiver to sender.
#include "vtkRadiosityOutputs.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include "hierarchy/cluster.h"
#include "solver/link_transport.h"
#include "emitters/external_source.h"
#include "solver/solver.h"

using terralux::Vec3;

void vtkRadiosityOutputs::BuildLinks(const terralux::HierarchicalRadiosity& solver, vtkPolyData* output)
{
  const terralux::Cluster* root = solver.root();
  const double reach = glm::length(root->high() - root->low());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkIntArray> level;
  level->SetName("Level");
  vtkNew<vtkDoubleArray> power;
  power->SetName("Power");
  vtkNew<vtkIntArray> sender, senderLevel;
  sender->SetName("Sender"); // what sends: 0 a surface or cluster, 1 a sky patch, 2 the sun
  senderLevel->SetName("SenderLevel");
  for (const auto& element : solver.elements().all())
  {
    for (const terralux::Link& link : element->Incoming)
    {
      const Vec3 from = element->centre();
      Vec3 to = link.sender->centre();
      const terralux::ExternalSource* source = link.sender->asExternal();
      if (source)
        to = from + reach * source->direction(); // sources at infinity: drawn toward the sky
      const vtkIdType a = points->InsertNextPoint(from.x, from.y, from.z);
      const vtkIdType b = points->InsertNextPoint(to.x, to.y, to.z);
      const vtkIdType ids[2] = { a, b };
      lines->InsertNextCell(2, ids);
      level->InsertNextValue(element->level());
      power->InsertNextValue(terralux::linkPower(*element, link));
      sender->InsertNextValue(!source ? 0 : (source->category() == terralux::SunLight ? 2 : 1));
      senderLevel->InsertNextValue(link.sender->level());
    }
  }
  output->SetPoints(points);
  output->SetLines(lines);
  output->GetCellData()->AddArray(level);
  output->GetCellData()->AddArray(power);
  output->GetCellData()->AddArray(sender);
  output->GetCellData()->AddArray(senderLevel);
}
