# The seconds the longest fast tests took (a fresh clone's `make test`, 2026-12-06, AMD Zen 5, 2 cores;
# dem.batch_loops_vectorise since reads the build's report and takes a second). ctest -j starts
# the costliest tests first once it has timings of its own (build/Testing/Temporary/CTestCostData.txt);
# a fresh clone has none and would start them in the order they are declared, the long end-to-end
# runs among the last, one running alone at the end. These costs (the COST property, applied by
# trapdem_test_costs() and the test programs' properties files) order that first run. A test not
# listed costs 0; a name listed that no longer exists is ignored.
set(trapdem_test_cost_python.module 29)
set(trapdem_test_cost_ReplicateStudy.TwoCasesTwoSeedsAndTheElementTest 24)
set(trapdem_test_cost_outputs.tiny_clump_run 22)
set(trapdem_test_cost_PackingStart.TheDocsExampleStartsFromTheTinyPresetsOwnDeposit 20)
set(trapdem_test_cost_TinyRun.ClumpsPourSettleSpinAndLower 18)
set(trapdem_test_cost_slurm.cluster_from_long_path 17)
set(trapdem_test_cost_StudyRun.ReportFiguresInSvgAndPdf 17)
set(trapdem_test_cost_Calibrate.PivOfARenderedTinyRunRanksItsOwnParametersFirst 17)
set(trapdem_test_cost_StudyRun.KilledDuringTheSecondCaseAndStartedAgainGivesTheSameReport 16)
set(trapdem_test_cost_StudyRun.StopAfterStopsTheRunningCaseWithItsCheckpointAndTheSameCommandCarriesOn 14)  # 2026-12-07: 26 s beside a 2-thread run, so not measured quiet; a straight study and a bit
set(trapdem_test_cost_PackingStart.AClumpRunsSnapshotStartsARunOfTheSameClumps 14)
set(trapdem_test_cost_StudyRun.PageOpensInHeadlessChromiumWithoutMissingImagesOrConsoleErrors 13)
set(trapdem_test_cost_SlurmCluster.CancelledCaseResumesWhenTheStudyIsSubmittedAgain 12)
set(trapdem_test_cost_SlurmCluster.SubmittedStudyEndsWithTheNumbersOfALocalRun 11)
set(trapdem_test_cost_TinyRun.AllStagesLoadsAndArching 10)
set(trapdem_test_cost_ShearBandRidges.PlanarBandsInCorrelatedNoise 10)
set(trapdem_test_cost_StudyRun.AFinishedRunWithoutANewKeyOrWithAnotherDescriptionIsKept 8)
set(trapdem_test_cost_Hopper.ABoxFullBeforeTheFillHeightIsSaidSo 7)
set(trapdem_test_cost_python.notebook 7)
set(trapdem_test_cost_StudyRun.AnotherScaleInTheSameFolderIsRefused 7)
set(trapdem_test_cost_StudyRun.ReportHasEveryFigureAndMeasuredNumbers 7)
set(trapdem_test_cost_StudyRun.AFinishedRunWithAnotherValueOrAnUnknownKeyIsRefused 7)
set(trapdem_test_cost_StudyRun.ACaseWhoseConfigurationChangedIsRefused 6)
set(trapdem_test_cost_StudyRun.StudyJsonNamesTheStudyFileRelativeToTheFolder 6)
set(trapdem_test_cost_TinyRun.ResumedRunEndsIdentical 6)
set(trapdem_test_cost_slurm.cluster_stop 6)
set(trapdem_test_cost_CentrifugeRun.ResumedInTheFrameEndsIdentical 6)
set(trapdem_test_cost_outputs.tiny_run 6)
set(trapdem_test_cost_HostLoad.TwoRunsStartedTogetherSeeEachOther 5)
set(trapdem_test_cost_mpi.ExperimentOnRanks.3ranks 5)
set(trapdem_test_cost_Collect.RunsTheElementTestsAndReportsWithoutStartingARun 5)
set(trapdem_test_cost_study.straight_run 7)
