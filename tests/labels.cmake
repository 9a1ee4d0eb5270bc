# CTest labels of the GoogleTest cases (see clips_tests in CMakeLists.txt).
# Per test executable: CLIPS_DATASET_TESTS_<module> lists, as a GoogleTest
# filter (patterns joined by ':'), the tests that need the paper's dataset
# (../shared/dataset or $CLIPS_DATASET); CLIPS_SLOW_TESTS_<module> the ones
# that take half a minute or more without it (label slow), and
# CLIPS_SLOW_DATASET_TESTS_<module> the slow ones that need it (labels slow and
# dataset), and CLIPS_BROWSER_TESTS_<module> the ones that need headless
# Chromium (label browser). CLIPS_INTEGRATION_TESTS_<module> lists the tests
# that need neither but take a second or more: they start the clips binary or
# a loopback server, train a language model, or search thousands of states
# (label integration). The lists must not overlap. Every other test is
# labelled unit and must run in well under a second without the dataset or a
# browser: `ctest -L unit` as a whole takes under half a minute. Value-
# parameterised tests are named Instance/Suite.Test/Param.
# A test missing here that needs the dataset would skip under `ctest -L unit`.

set(CLIPS_DATASET_TESTS_app "CliPlan.RunTimeLimitStopsRtaaAndAstar:CliPlan.WeightedSearchFindsAPlanForEveryGem:CliPlan.JsonReportsTheTimeLimitStatus:BenchFilesTest.PaperColumnBesideThePapersDataset:BenchFilesTest.ACopyWithOtherProblemsIsNotThePapers:CliObservations.OnThePapersDataset")
set(CLIPS_DATASET_TESTS_api "Session.ReplayMatchesClipsInferOnThePapersDataset")
set(CLIPS_DATASET_TESTS_commands "FewShotFile.SharedReferenceFileLoadsAndAgrees")
set(CLIPS_DATASET_TESTS_data "DatasetInput.*Vh*:DatasetInput.SharedDatasetsStillValidate")
set(CLIPS_DATASET_TESTS_eval "PaperBehaviour.*")
set(CLIPS_DATASET_TESTS_scenes "Scenes.VirtualHomeSceneIfDatasetPresent")
set(CLIPS_SLOW_DATASET_TESTS_eval "Paraphrases.*:VirtualHomeRewordings.*:Paraphrases/VirtualHomeRewordings.*")
set(CLIPS_BROWSER_TESTS_report "BenchReportTest.RendersInHeadlessChromium")
set(CLIPS_DATASET_TESTS_inference "DkgDataset.UtteranceRaisesTrueGoalOn2_1Keys:VhDataset.*")
set(CLIPS_SLOW_DATASET_TESTS_inference "DkgDataset.AllPlansThreeModalities")
set(CLIPS_DATASET_TESTS_language "ListenCli.JsonShape:ListenCli.UnreadableUtteranceIsFlagged:ListenCli.AllCommandsSumToOne:ListenCli.BlankUtteranceExitsTwo:ListenCli.TableOutput:DkgListener.*:VhListener.*")
set(CLIPS_SLOW_DATASET_TESTS_language "ListenerQuality.*")
set(CLIPS_DATASET_TESTS_render "GridRender.DatasetMaps")
set(CLIPS_DATASET_TESTS_pddl "Parser.ReadsBothSharedDatasetDomains")
set(CLIPS_DATASET_TESTS_search "AStar.DefaultHeuristicMatchesUniformCostSearchOnTheDataset:DkgDistanceHeuristic.*OnDataset*:DkgMstHeuristic.OverestimatesRarelyAndLittleAndFindsEveryDeadEnd:DkgMstHeuristic.BoundedEstimateEqualsTheMinimumOverClauses")
set(CLIPS_SLOW_DATASET_TESTS_search "StripsExport.SameOptimalCostOnTheDataset")
set(CLIPS_SLOW_TESTS_app "IpcPlan.*")
set(CLIPS_SLOW_TESTS_search "StripsExport.SameOptimalCostFromMidPlanStates:StripsExport.SameOptimalCostOnExampleProblems:StripsExport.ConjunctiveGoalsAndUnsupportedGoals:AStar.HMaxMatchesUniformCostSearchOnExampleProblems")

# Trains the six repo datasets' models for the CLI, the test and Python when the cache is cold (about 2.5 min).
set(CLIPS_SLOW_TESTS_engine "FrontEnds.EveryRepoDatasetIsHeardAlikeByEveryFrontEnd")
set(CLIPS_INTEGRATION_TESTS_engine "FrontEnds.CliSessionPythonAndServerAgreeStepByStep:AssistantWeights.*:ParticleOptionTable.ABadValueGivesTheSameErrorFromCliPythonAndServer:ParticleOptionTable.TheServerTakesASessionsParticleOptions")
set(CLIPS_INTEGRATION_TESTS_api "Session.AssistsWithThePacksNoOpAndTurnPredicate:Session.ReplayMatchesClipsInferOnTheRepoExamples:Session.TwoSessionsOnTwoThreadsAgreeWithOneThread")
set(CLIPS_INTEGRATION_TESTS_app "MapWords.*:CliOwnDomain.*:GenerateCli.*:BenchFilesTest.PosteriorsResultsAndProvenance:CliNumbers.BadValuesAreRefusedAtParseTime:CliObservations.ErrorsNameTheAction:CliPlanLimits.*:CliCallLimits.*:UnreadableUtterance.*:BenchCli.*:CliBrokenPlan.*:CliExitCodes.*:CliStreams.*:CliSmaller.*:CliObservations.ActionsFromAPlanFile:CliObservations.AssistNamesTheAssistantsNextAction:CliObservations.InlineActionsReproduceTheDatasetPlan:CliObservations.TheUtteranceStepMatters:CliPlan.EmptyGoalsAreRejected:CliPlan.HelpSaysBudgetsArePerSearchAndOffersARunLimit:CliPlan.ProblemMustMatchFromPlan:BenchShardTest.*:BenchShardCli.BadShardValuesAreUsageErrors:BenchShardCli.EmptyShardWritesValidFilesAndMerges:BenchShardCli.UnloadablePlanIsShardedAndMergedLikeTheOthers")
set(CLIPS_INTEGRATION_TESTS_eval "CliHardening.*:CliRefusesBadInput.*:BenchLmFlags.*:InferCli.*:ParticleCli.*:LmServersCli.*")
set(CLIPS_INTEGRATION_TESTS_studies "ScalingRun.*")
set(CLIPS_INTEGRATION_TESTS_generate "GenerateDataset.SmallSetLoadsAndEveryPlanChecks:GenerateDataset.TheSeedDecidesEveryByte")
set(CLIPS_INTEGRATION_TESTS_report "BenchReportTest.ReportFilesAndHtml:BenchReportTest.ResultsCsvHasOneRowPerPlanAndMethod:BenchReportTest.SummaryJson")
set(CLIPS_INTEGRATION_TESTS_multimodal "MultimodalServer.*")
set(CLIPS_INTEGRATION_TESTS_scenes "RenderCli.*")
set(CLIPS_INTEGRATION_TESTS_inference "ConcurrentInference.*:ParallelRefinement.*:ParticleExamples.*:AloneTwins.*:DelegatingSpeaker.*:JointStatement.*:FunctionWords.*:AddressedClause.*:GoalWithCommand.*")
set(CLIPS_INTEGRATION_TESTS_language "ListenCli.LmScorePrintsLogProbAndBackend:ListenCli.LmScoreReadsWindowsLineEndingsAndRefusesNonPromptFiles:LmDomain.*")
set(CLIPS_INTEGRATION_TESTS_lm "AlignmentBehaviour.RareColoursAreCopiedAsReadilyAsFrequentOnes:AlignmentGolden.*:EmbeddedCache.*:EmbeddedSnapshot.*:HttpClientTest.ReturnsNonRetryableStatusesWithoutRetrying:HttpClientTest.StopsReadingAnEndlessReplyAtTheCap:OpenAiCompletionsTest.EndlessReplyStopsAtTheDefaultCap:DomainCorpus.*")
set(CLIPS_INTEGRATION_TESTS_pddl "ReaderLimit.HugeFileOfRepeatedTokensFailsFast")
set(CLIPS_INTEGRATION_TESTS_search "StateGraph.AStateWithMoreThan65535SuccessorsIsStored:AStarWorkspace.ReusedWorkspaceMatchesFreshSearches:DkgDistanceHeuristic.AdmissibleAgainstExactCostOnHandMaps:HMax.AdmissibleAndConsistentOnRandomWalks:Rtaa.PathReuseMakesLaterRefinementsCheaper:StripsExport.FrozenRobotMayOnlyWaitOrHandOver:TimeLimit.*:WorkshopGoals.EveryCandidateGoalIsSolvableFromTheInitialState:HFF.BoundsAndPlansOnTheWorkshop:LmCut.AdmissibleOnRandomWalks:LmCut.SameOptimalCostsAsHMaxOnTheWorkshop:StripsGrounded.SameOptimalCostsAsClipsPlanOnTheWorkshop")
set(CLIPS_INTEGRATION_TESTS_serve "ServiceUnderHostileUse.*:ServeConnections.*:Fixture.PlayHearAssistUndoResetAndSwitchMethod:Fixture.SessionsRunInParallelAndIndependently:ServeLoopback.*:ServeHardening.*:PackSessionsIdle.*")
set(CLIPS_INTEGRATION_TESTS_domains "DkgScale.*")
